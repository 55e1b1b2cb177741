//! The emitted shaders: the committed `shaders-out/` is exactly what the source emits
//! now (golden test), every artifact validates with the external tools, and the include
//! libraries compile inside a test shader of each language.
//!
//! Tools: `spirv-val` (Debian `spirv-tools`), `glslangValidator` (Debian `glslang-tools`).
//! `.ci/run` installs them; when `CI=true` a missing tool fails the test, otherwise it is
//! reported loudly and the tool's check is skipped. MSL has no validator on Linux: MSL output
//! is what naga wrote from a module naga validated, nothing more is claimed.

use airlight_shaders::targets::{default_out_dir, render, validate, EmitOptions, NODE_COUNTS};
use airlight_tests::repo_root;
use std::path::Path;
use std::process::Command;

fn tool(name: &str) -> bool {
    let ok = Command::new(name).arg("--version").output().is_ok();
    if !ok {
        if std::env::var("CI").as_deref() == Ok("true") {
            panic!("{name} is not installed (CI=true: install spirv-tools and glslang-tools)");
        }
        eprintln!("WARNING: {name} not installed; its checks are SKIPPED (CI fails instead)");
    }
    ok
}

fn run(cmd: &mut Command) {
    let out = cmd.output().expect("spawn");
    assert!(
        out.status.success(),
        "{:?} failed:\n{}\n{}",
        cmd,
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
}

#[test]
fn shaders_out_is_what_the_source_emits() {
    let files = render(&EmitOptions::default()).expect("render");
    let dir = default_out_dir();
    let problems = airlight_shaders::targets::check(&dir, &EmitOptions::default()).unwrap();
    assert!(problems.is_empty(), "shaders-out/ is stale, run `cargo run -p airlight-codegen -- emit`:\n{}", problems.join("\n"));
    assert_eq!(files.len(), 22);
}

/// shaders-out/README.md's table gives each file's size in bytes; it must be the committed
/// file's (it went stale twice before this test).
#[test]
fn readme_sizes_are_current() {
    let dir = default_out_dir();
    let readme = std::fs::read_to_string(dir.join("README.md")).expect("shaders-out/README.md");
    let mut rows = 0;
    let counts = format!("{{{}}}", NODE_COUNTS.map(|n| n.to_string()).join(","));
    for line in readme.lines().filter(|l| l.starts_with("| `") && l.contains(&counts)) {
        let pattern = line.split('`').nth(1).unwrap();
        let sizes = line.trim_end_matches(" |").rsplit("| ").next().unwrap();
        let listed: Vec<u64> = sizes.split(" / ").map(|n| n.replace(' ', "").parse().expect(line)).collect();
        for (n, want) in NODE_COUNTS.iter().zip(&listed) {
            let file = dir.join(pattern.replace(&counts, &n.to_string()));
            let got = std::fs::metadata(&file).unwrap_or_else(|e| panic!("{}: {e}", file.display())).len();
            assert_eq!(got, *want, "shaders-out/README.md lists {} as {want} bytes; it has {got} (run scripts/update-shader-sizes.py)", file.display());
        }
        rows += 1;
    }
    assert_eq!(rows, 11, "rows of the size table in shaders-out/README.md");
}

/// A fresh directory for this test process's generated files.
fn scratch(name: &str) -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!("{name}-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

#[test]
fn spirv_validates() {
    if !tool("spirv-val") {
        return;
    }
    for n in NODE_COUNTS {
        let path = default_out_dir().join(format!("spirv/airlight_{n}.spv"));
        run(Command::new("spirv-val").arg("--target-env").arg("vulkan1.0").arg(&path));
    }
}

#[test]
fn glsl_and_hlsl_compute_shaders_compile() {
    if !tool("glslangValidator") {
        return;
    }
    let tmp = scratch("airlight-shaders");
    for n in NODE_COUNTS {
        let dir = default_out_dir();
        run(Command::new("glslangValidator").args(["-V", "--target-env", "vulkan1.0", "-o"]).arg(tmp.join("c.spv")).arg(dir.join(format!("glsl/airlight_{n}.comp"))));
        run(Command::new("glslangValidator").args(["-V", "-D", "-e", "airlight_main", "-S", "comp", "-o"]).arg(tmp.join("h.spv")).arg(dir.join(format!("hlsl/airlight_{n}.hlsl"))));
    }
}

/// The scene the HLSL test shaders build, with the library's constructor.
const SCENE_HLSL: &str = "ConstructAirlightScene(float3(0.0, 0.0, 0.0), 0.0, float3(1.0, 0.0, 0.0), 25.0, float3(5.0, 1.0, 0.0), 100.0, float3(0.0, -1.0, 0.0), 4.0, 0.0, 0.08, 0.1, 0.5, 0.0, 0.0, 1u, 2u, 0u, 0.0, 0u, 0.0, float3(5.0, 1.0, 0.0), 0u, float3(0.0, 0.0, 0.0))";

const SCENE_GLSL: &str = "AirlightScene(vec3(0.0), 0.0, vec3(1.0, 0.0, 0.0), 25.0, vec3(5.0, 1.0, 0.0), 100.0, vec3(0.0, -1.0, 0.0), 4.0, 0.0, 0.08, 0.1, 0.5, 0.0, 0.0, 1u, 2u, 0u, 0.0, 0u, 0.0, vec3(5.0, 1.0, 0.0), 0u, vec3(0.0, 0.0, 0.0))";

fn paste(path: &Path, before: &str, after: &str) -> String {
    format!("{before}\n{}\n{after}\n", std::fs::read_to_string(path).unwrap())
}

/// The include libraries compile inside a user's shader, pasted as an `#include` would, calling
/// the full entry and the area lights' (`airlight_in_scatter_area`).
#[test]
fn include_libraries_compile_in_a_test_shader() {
    if !tool("glslangValidator") {
        return;
    }
    let tmp = scratch("airlight-lib");
    let dir = default_out_dir();
    for n in NODE_COUNTS {
        let g450 = paste(
            &dir.join(format!("glsl/airlight_lib_{n}.glsl")),
            "#version 450",
            &format!("layout(local_size_x = 1) in;\nlayout(std430, binding = 0) buffer Out {{ float v[]; }};\nvoid main() {{ v[0] = airlight_in_scatter({SCENE_GLSL}).in_scatter + airlight_in_scatter_area({SCENE_GLSL}).in_scatter; }}"),
        );
        std::fs::write(tmp.join("t.comp"), g450).unwrap();
        run(Command::new("glslangValidator").args(["-V", "-o"]).arg(tmp.join("t.spv")).arg(tmp.join("t.comp")));
        let es = paste(
            &dir.join(format!("glsl/airlight_lib_{n}_es300.glsl")),
            "#version 300 es\nprecision highp float;\nprecision highp int;",
            &format!("out vec4 color;\nvoid main() {{ color = vec4(airlight_in_scatter({SCENE_GLSL}).in_scatter, airlight_in_scatter_area({SCENE_GLSL}).in_scatter, 0.0, 1.0); }}"),
        );
        std::fs::write(tmp.join("t.frag"), es).unwrap();
        run(Command::new("glslangValidator").arg(tmp.join("t.frag")));
        let hl = paste(
            &dir.join(format!("hlsl/airlight_lib_{n}.hlsl")),
            "",
            &format!("RWStructuredBuffer<float> v : register(u0);\n[numthreads(1, 1, 1)]\nvoid test_main() {{\n    AirlightScene s = {SCENE_HLSL};\n    v[0] = airlight_in_scatter(s).in_scatter + airlight_in_scatter_area(s).in_scatter;\n}}"),
        );
        std::fs::write(tmp.join("t.hlsl"), hl).unwrap();
        run(Command::new("glslangValidator").args(["-V", "-D", "-e", "test_main", "-S", "comp", "-o"]).arg(tmp.join("h.spv")).arg(tmp.join("t.hlsl")));
    }
}

/// A user's HLSL file that includes the library twice (its guard keeps the second out) next to
/// another naga-emitted file — whose own helpers (`naga_mod`, `Constructarray…`) the library
/// would redefine if its names were not all prefixed — compiles with glslang.
#[test]
fn hlsl_library_shares_a_file_with_another_naga_output() {
    if !tool("glslangValidator") {
        return;
    }
    let tmp = scratch("airlight-hlsl");
    // another naga output: a WGSL function with an integer remainder and an array constructor
    let other = "fn other_hash(x: u32, y: u32) -> f32 {\n    let a = array<f32, 4>(1.0, 2.0, 3.0, 4.0);\n    return a[x % 4u] + f32(y % 3u);\n}\n@compute @workgroup_size(1)\nfn other_main() { _ = other_hash(1u, 2u); }\n";
    let module = naga::front::wgsl::parse_str(other).unwrap();
    let info = naga::valid::Validator::new(naga::valid::ValidationFlags::all(), naga::valid::Capabilities::default()).validate(&module).unwrap();
    let options = naga::back::hlsl::Options { shader_model: naga::back::hlsl::ShaderModel::V5_1, ..Default::default() };
    let pipeline = naga::back::hlsl::PipelineOptions { entry_point: Some((naga::ShaderStage::Compute, "other_main".to_string())) };
    let mut other_hlsl = String::new();
    naga::back::hlsl::Writer::new(&mut other_hlsl, &options, &pipeline).write(&module, &info, None).unwrap();
    assert!(other_hlsl.contains("naga_mod") && other_hlsl.contains("Constructarray4_float_"), "the other file no longer has the helpers this test is about:\n{other_hlsl}");
    // keep its functions, not its entry point
    let other_hlsl = other_hlsl.split("[numthreads").next().unwrap().to_string();
    std::fs::write(tmp.join("other.hlsl"), &other_hlsl).unwrap();
    let dir = default_out_dir();
    for n in NODE_COUNTS {
        std::fs::copy(dir.join(format!("hlsl/airlight_lib_{n}.hlsl")), tmp.join("airlight.hlsl")).unwrap();
        let user = format!(
            "#include \"airlight.hlsl\"\n#include \"other.hlsl\"\n#include \"airlight.hlsl\"\nRWStructuredBuffer<float> v : register(u0);\n[numthreads(1, 1, 1)]\nvoid test_main() {{\n    AirlightScene s = {SCENE_HLSL};\n    v[0] = airlight_in_scatter(s).in_scatter + other_hash(3u, 5u);\n}}\n",
        );
        std::fs::write(tmp.join("user.hlsl"), user).unwrap();
        run(Command::new("glslangValidator").args(["-V", "-D", "-e", "test_main", "-S", "comp", "-o"]).arg(tmp.join("u.spv")).arg(tmp.join("user.hlsl")));
    }
}

/// Every global name of the HLSL and MSL files is the library's: `airlight_…`, `AIRLIGHT_…`,
/// `Airlight…` structs and HLSL's `ConstructAirlight…` constructors (naga's own helpers carry
/// the prefix too).
#[test]
fn hlsl_and_msl_globals_are_prefixed() {
    let dir = default_out_dir();
    let mut bad = Vec::new();
    for (folder, ext) in [("hlsl", "hlsl"), ("msl", "metal")] {
        for entry in std::fs::read_dir(dir.join(folder)).unwrap().flatten() {
            let path = entry.path();
            if path.extension().and_then(|e| e.to_str()) != Some(ext) {
                continue;
            }
            let text = std::fs::read_to_string(&path).unwrap();
            for line in text.lines().filter(|l| l.starts_with(|c: char| c.is_ascii_alphabetic())) {
                if line.starts_with("using ") {
                    continue;
                }
                // the declared name: before `(` for a function, else the last word before `=`, `[`, `{` or `;`
                let line = line.replace("::", "__");
                let head = line.split(['(', '=', '[', '{', ';', ':']).next().unwrap_or("");
                let Some(name) = head.split_whitespace().last() else { continue };
                let ok = ["airlight_", "AIRLIGHT_", "Airlight", "ConstructAirlight"].iter().any(|p| name.starts_with(p))
                    || (line.starts_with("kernel void") || line.contains(" airlight_main"));
                if !ok {
                    bad.push(format!("{}: {line}", path.display()));
                }
            }
        }
    }
    assert!(bad.is_empty(), "unprefixed global names:\n{}", bad.join("\n"));
}

/// The emitted WGSL re-validates in naga, on its own (compute) and inside a user's module
/// (library).
#[test]
fn wgsl_revalidates_in_naga() {
    let dir = default_out_dir();
    for n in NODE_COUNTS {
        let c = std::fs::read_to_string(dir.join(format!("wgsl/airlight_{n}.wgsl"))).unwrap();
        validate(&c).unwrap_or_else(|e| panic!("wgsl/airlight_{n}.wgsl: {e}"));
        let l = std::fs::read_to_string(dir.join(format!("wgsl/airlight_lib_{n}.wgsl"))).unwrap();
        let user = format!(
            "{l}\n@group(0) @binding(0) var<storage, read_write> v: array<f32>;\n@compute @workgroup_size(1)\nfn test_main() {{\n    v[0] = airlight_in_scatter(AirlightScene(vec3<f32>(0.0), 0.0, vec3<f32>(1.0, 0.0, 0.0), 25.0, vec3<f32>(5.0, 1.0, 0.0), 100.0, vec3<f32>(0.0, -1.0, 0.0), 4.0, 0.0, 0.08, 0.1, 0.5, 0.0, 0.0, 1u, 2u, 0u, 0.0, 0u, 0.0, vec3<f32>(5.0, 1.0, 0.0), 0u, vec3<f32>(0.0, 0.0, 0.0))).in_scatter;\n}}\n"
        );
        validate(&user).unwrap_or_else(|e| panic!("wgsl/airlight_lib_{n}.wgsl in a user module: {e}"));
    }
    let _ = repo_root();
}

/// The fenced block after `<!-- snippet: {tag} -->` in shaders-out/README.md.
fn readme_snippet(readme: &str, tag: &str) -> String {
    let marker = format!("<!-- snippet: {tag} -->\n```");
    let at = readme.find(&marker).unwrap_or_else(|| panic!("shaders-out/README.md has no snippet `{tag}`"));
    let body = &readme[at + marker.len()..];
    let body = &body[body.find('\n').unwrap() + 1..];
    body[..body.find("```").unwrap()].to_string()
}

/// `snippet` with its `// <file pasted here>` line replaced by that file of shaders-out/.
fn pasted(snippet: &str, file: &str) -> String {
    let line = format!("// <{file} pasted here>");
    assert!(snippet.contains(&line), "the snippet does not say where {file} goes");
    snippet.replace(&line, &std::fs::read_to_string(default_out_dir().join(file)).unwrap())
}

/// Every usage snippet of shaders-out/README.md compiles exactly as shown, the library where
/// it says (an `#include` resolved from shaders-out/, or pasted at its marker line): WGSL by
/// naga, GLSL 450 by glslang to SPIR-V (then `spirv-val`), GLSL ES 3.00 and HLSL by glslang.
/// The MSL snippet has no compiler on Linux; it is checked to call only what the MSL library
/// defines.
#[test]
fn readme_snippets_compile() {
    let dir = default_out_dir();
    let readme = std::fs::read_to_string(dir.join("README.md")).unwrap();
    let wgsl = pasted(&readme_snippet(&readme, "wgsl"), "wgsl/airlight_lib_8.wgsl");
    validate(&wgsl).unwrap_or_else(|e| panic!("the WGSL snippet: {e}"));
    let msl = readme_snippet(&readme, "msl");
    let msl_lib = std::fs::read_to_string(dir.join("msl/airlight_lib_8.metal")).unwrap();
    let code: String = msl.lines().filter(|l| !l.starts_with("#include")).collect::<Vec<_>>().join("\n");
    for name in code.split(|c: char| !(c.is_alphanumeric() || c == '_')).filter(|w| w.starts_with("airlight_") || w.starts_with("Airlight") || w.starts_with("AIRLIGHT_")) {
        assert!(msl_lib.contains(name), "the MSL snippet uses {name}, which the MSL library does not define");
    }
    if !tool("glslangValidator") || !tool("spirv-val") {
        return;
    }
    let tmp = scratch("airlight-snippets");
    std::fs::write(tmp.join("fog.frag"), readme_snippet(&readme, "glsl450")).unwrap();
    run(Command::new("glslangValidator").arg("-V").arg(format!("-I{}", dir.join("glsl").display())).arg("-o").arg(tmp.join("fog.spv")).arg(tmp.join("fog.frag")));
    run(Command::new("spirv-val").args(["--target-env", "vulkan1.0"]).arg(tmp.join("fog.spv")));
    let size = std::fs::metadata(tmp.join("fog.spv")).unwrap().len();
    println!("GLSL 450 snippet as SPIR-V (glslang): {size} bytes");
    std::fs::write(tmp.join("fog_es.frag"), pasted(&readme_snippet(&readme, "es300"), "glsl/airlight_lib_8_es300.glsl")).unwrap();
    run(Command::new("glslangValidator").arg(tmp.join("fog_es.frag")));
    std::fs::write(tmp.join("fog.hlsl"), readme_snippet(&readme, "hlsl")).unwrap();
    run(Command::new("glslangValidator").args(["-V", "-D", "-e", "fog_glow", "-S", "frag"]).arg(format!("-I{}", dir.join("hlsl").display())).arg("-o").arg(tmp.join("fog_hlsl.spv")).arg(tmp.join("fog.hlsl")));
}

/// The naga_oil module variant composes into a user's shader that imports from it by name
/// (as Bevy's shader imports do), and the composed module validates.
#[test]
fn naga_oil_import_module_composes() {
    use naga_oil::compose::{ComposableModuleDescriptor, Composer, NagaModuleDescriptor};
    let dir = default_out_dir();
    for n in NODE_COUNTS {
        let file = format!("wgsl/airlight_lib_{n}_import.wgsl");
        let library = std::fs::read_to_string(dir.join(&file)).unwrap();
        let mut composer = Composer::default();
        if let Err(e) = composer.add_composable_module(ComposableModuleDescriptor { source: &library, file_path: &file, ..Default::default() }) {
            panic!("{file} as a naga_oil module: {}", e.emit_to_string(&composer));
        }
        let user = "#import airlight::{airlight_in_scatter, airlight_scene, airlight_ray, airlight_spot, airlight_medium, airlight_henyey_greenstein, AIRLIGHT_STATUS_OK}

@fragment
fn fog_glow(@location(0) world_pos: vec3<f32>) -> @location(0) vec4<f32> {
    let eye = vec3<f32>(0.0, 1.7, 0.0);
    let to_p = world_pos - eye;
    let r = airlight_in_scatter(airlight_scene(
        airlight_ray(eye, to_p, 0.0, length(to_p)),
        airlight_spot(vec3<f32>(5.0, 4.0, 0.0), 100.0, vec3<f32>(0.0, -1.0, 0.0), 0.95, 0.8),
        airlight_medium(0.05, 0.1),
        airlight_henyey_greenstein(0.9)));
    return vec4<f32>(vec3<f32>(select(0.0, r.in_scatter, r.status == AIRLIGHT_STATUS_OK)), 1.0);
}
";
        let module = composer
            .make_naga_module(NagaModuleDescriptor { source: user, file_path: "user.wgsl", ..Default::default() })
            .unwrap_or_else(|e| panic!("composing a user shader with {file}: {}", e.emit_to_string(&composer)));
        naga::valid::Validator::new(naga::valid::ValidationFlags::all(), naga::valid::Capabilities::default())
            .validate(&module)
            .unwrap_or_else(|e| panic!("the composed module ({file}): {e:?}"));
    }
}
