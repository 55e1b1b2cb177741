//! The `airlight` command: evaluate scenes, emit and check shaders, verify a GPU, render.
//! Arguments are parsed by clap; each command's help is `airlight CMD --help`.

use airlight::Expansion;
use airlight_codegen::eval::{self, Backend, EvalOptions, Precision};
use airlight_shaders::targets::{self, EmitOptions, Target};
use clap::{Parser, Subcommand, ValueEnum};
use std::path::PathBuf;
use std::process::ExitCode;

/// Analytic fog glow (single-scattered air-light) of point and spot lights.
#[derive(Parser)]
#[command(name = "airlight", version, propagate_version = true)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Evaluate scene records: JSON lines in, one JSON line out per line in.
    #[command(long_about = EVAL_ABOUT)]
    Eval(EvalArgs),
    /// Write the shaders through naga.
    ///
    /// The compute entry point and the include library, per target and node count; everything
    /// is rendered and validated before anything is written.
    Emit(EmitArgs),
    /// Check that the shaders are what `emit` would write now.
    ///
    /// Exit 1 and list the stale, missing or unexpected files when DIR is not what `emit`
    /// would write now.
    Check(EmitArgs),
    /// Check this machine's GPU against the CPU kernel.
    ///
    /// Random scenes through the committed compute shader, compared with the f32 CPU kernel;
    /// prints the adapter, the differences and a PASS/FAIL verdict (exit 1 on FAIL).
    Verify(VerifyArgs),
    /// Render the example pictures to PNG, with error heat maps.
    #[command(long_about = RENDER_ABOUT)]
    Render(RenderArgs),
}

const EVAL_ABOUT: &str = "\
Evaluate scene records: JSON lines on stdin, one JSON line per input line on stdout, in input
order and written as soon as it is computed (usable as a co-process): {\"in_scatter\": L}
(\"inf\" for +infinity, when the light lies exactly on the segment) or
{\"error\": \"line N: field: problem\"}. A bad line (invalid JSON or UTF-8, an empty line, an
unknown or missing field, an invalid value) gets its error line and does not stop the others.
A record's \"id\" (any JSON value) is echoed first in its answer: {\"id\": 7, \"in_scatter\": L}.

Record: {\"ray\": {\"origin\": [x,y,z], \"dir\": [x,y,z], \"t_min\": 0, \"t_max\": 25 | null},
         \"medium\": {\"sigma_s\": 0.08, \"sigma_t\": 0.1},
         \"light\": {\"position\": [x,y,z], \"intensity\": 100,
                   \"distribution\": {\"kind\": \"isotropic\" | \"two_lobed\" (axis, power)
                                    | \"spot\" (axis, cos_inner, cos_outer)}},
         \"phase\": {\"kind\": \"isotropic\" | \"rayleigh\" | \"henyey_greenstein\" (g)
                   | \"schlick\" (k) | \"cornette_shanks\" (g)
                   | \"two_lobe_henyey_greenstein\" (g1, g2, w)}}
t_max null or absent means +infinity, t_min absent 0, distribution absent isotropic, phase
absent isotropic. Any other key is an error (with a suggestion when it is close to a known one).
`dir` need not be unit length (it is normalised); t_min and t_max are world distances.
A segment light (CPU default path, or --backend gpu): \"light\": {\"shape\": \"segment\", \"a\": [x,y,z],
\"b\": [x,y,z], \"intensity\": I, \"distribution\": {...}}, every point emitting I per unit length.
Area lights of uniform radiance L (CPU default path; --backend gpu: the bounded method): \"light\": {\"shape\": \"disc\", \"center\": [x,y,z],
\"normal\": [x,y,z], \"radius\": R, \"radiance\": L} or {\"shape\": \"rectangle\", \"corner\": [x,y,z],
\"edge_u\": [x,y,z], \"edge_v\": [x,y,z], \"radiance\": L} (emitting on the side of edge_u x edge_v)
or {\"shape\": \"sphere\", \"center\": [x,y,z], \"radius\": R, \"radiance\": L}; each may add
\"emission\": {\"kind\": \"cosine_lobe\", \"power\": p} (every element max(0, n.w)^p, p in 1..=1024).
A surface point (CPU default path; --backend gpu: lit by an omni light), in place of the ray: \"surface\": {\"position\": [x,y,z],
\"normal\": [x,y,z], \"brdf\": {\"kind\": \"lambert\", \"albedo\": a} | {\"kind\": \"phong\", \"k_s\": k,
\"exponent\": n, \"view\": [x,y,z]}} -> {\"surface_air_light\": L}: the air-light reflected towards
the eye, the in-scattered radiance of every ray from the point over its hemisphere times the BRDF.";

const RENDER_ABOUT: &str = "\
Render the pictures to PNG: a lighthouse with a two-lobed beam in thick brume, a foggy road with
headlights and a streetlamp, a stage under three coloured spotlights, a park bench in Rayleigh
mist, a street with a fluorescent tube and walls lit by the fog. Writes DIR/<scene>_<backend>.png per backend — cpu (the f64 kernel's default path), gpu
(the committed WGSL compute shader through wgpu, f32, 8 nodes per panel), reference
(brute-force adaptive quadrature of the integral, no closed forms) — and, with the reference,
error heat maps DIR/<scene>_error.png (cpu) and DIR/<scene>_error_gpu.png (shader): per-pixel
relative error against the reference, log10 scale from 1e-7 (black) through blue, green,
yellow to 1e-1 (red), with a colour bar along the bottom. Prints one summary line per scene
(times, max/median error); progress on stderr for renders that take more than a second.";

#[derive(Clone, Copy, ValueEnum)]
enum BackendArg {
    /// The CPU kernel.
    Cpu,
    /// The emitted compute shader through wgpu on this machine's GPU (f32); its point-light
    /// entry when every record is a point light.
    Gpu,
}

#[derive(Clone, Copy, ValueEnum)]
enum PrecisionArg {
    F32,
    F64,
}

#[derive(Clone, Copy, ValueEnum)]
enum ExpansionArg {
    Chebyshev,
    Taylor,
}

/// The term or node counts the shaders are emitted with (and the CPU's fixed method takes here).
#[derive(Clone, Copy, ValueEnum)]
enum Nodes {
    #[value(name = "8")]
    Eight,
    #[value(name = "12")]
    Twelve,
}

impl Nodes {
    fn count(self) -> usize {
        match self {
            Nodes::Eight => 8,
            Nodes::Twelve => 12,
        }
    }
}

#[derive(clap::Args)]
struct EvalArgs {
    /// Where records are evaluated (the GPU backend is f32; --precision and --expansion do
    /// not apply there).
    #[arg(long, value_enum, default_value = "cpu")]
    backend: BackendArg,
    /// Kernel precision.
    #[arg(long, value_enum, default_value = "f64")]
    precision: PrecisionArg,
    /// CPU: the paper's fixed-cost method with this many expansion terms, 1 to 16 (default:
    /// the kernel's error-controlled panels, within 1e-10 in f64 and 1e-4 in f32 of
    /// max(|exact|, tau·scale)). GPU: the shader with this many nodes per panel, 8 or 12
    /// (default 8).
    #[arg(long, value_parser = clap::value_parser!(u8).range(1..=16))]
    terms: Option<u8>,
    /// Polynomial expansion of --terms.
    #[arg(long, value_enum, default_value = "chebyshev")]
    expansion: ExpansionArg,
}

#[derive(clap::Args)]
struct EmitArgs {
    /// Output (emit) or checked (check) directory [default: the workspace's shaders-out/].
    #[arg(long, visible_alias = "dir")]
    out: Option<PathBuf>,
    /// Nodes per panel of the emitted shaders, a comma list.
    #[arg(long, value_enum, value_delimiter = ',', default_value = "8,12")]
    terms: Vec<Nodes>,
    /// Target languages, a comma list (wgsl, glsl, spirv, hlsl, msl) [default: all].
    #[arg(long, value_delimiter = ',')]
    targets: Vec<String>,
    /// The panels' relative tolerance, 1e-5 to 1e-1 [default: 1e-3, as shaders-out/]; looser
    /// is faster and less accurate (BENCHMARKS.md, GPU).
    #[arg(long)]
    tolerance: Option<f32>,
}

#[derive(clap::Args)]
struct VerifyArgs {
    /// Number of random scenes.
    #[arg(long, default_value_t = 10_000, value_parser = clap::value_parser!(u32).range(1..))]
    cases: u32,
    /// Nodes per panel of the shader under test.
    #[arg(long, value_enum, default_value = "8")]
    terms: Nodes,
}

#[derive(Clone, Copy, PartialEq, Eq, ValueEnum)]
enum RenderBackend {
    Cpu,
    Gpu,
    Reference,
    /// All three; a machine without a GPU adapter skips gpu with a warning.
    All,
}

#[derive(clap::Args)]
struct RenderArgs {
    /// lighthouse, road, stage, bench, street or all.
    #[arg(long, default_value = "all", value_parser = ["lighthouse", "road", "stage", "bench", "street", "all"])]
    scene: String,
    /// Image size in pixels, WxH (1..8192 each).
    #[arg(long, default_value = "480x270", value_parser = parse_size)]
    size: (u32, u32),
    /// Output directory, created if missing.
    #[arg(long, default_value = "renders")]
    out: PathBuf,
    /// Backends, a comma list.
    #[arg(long, value_enum, value_delimiter = ',', default_value = "all")]
    backend: Vec<RenderBackend>,
}

fn parse_size(v: &str) -> Result<(u32, u32), String> {
    let parsed = v.split_once(['x', 'X']).and_then(|(w, h)| Some((w.parse::<u32>().ok()?, h.parse::<u32>().ok()?)));
    match parsed {
        Some((w, h)) if w > 0 && h > 0 && w <= 8192 && h <= 8192 => Ok((w, h)),
        _ => Err("expected WxH with 1..8192 pixels each".to_string()),
    }
}

fn main() -> ExitCode {
    match Cli::parse().command {
        Command::Eval(a) => cmd_eval(a),
        Command::Emit(a) => cmd_emit(a, false),
        Command::Check(a) => cmd_emit(a, true),
        Command::Verify(a) => cmd_verify(a),
        Command::Render(a) => cmd_render(a),
    }
}

/// An I/O failure of `eval`'s output: a closed pipe (`eval … | head -1`) is the reader's
/// choice and ends the run quietly; anything else is reported.
fn output_failed(e: &std::io::Error) -> ExitCode {
    if e.kind() == std::io::ErrorKind::BrokenPipe {
        return ExitCode::SUCCESS;
    }
    eprintln!("airlight: {e}");
    ExitCode::from(1)
}

fn cmd_eval(a: EvalArgs) -> ExitCode {
    let opts = EvalOptions {
        backend: match a.backend {
            BackendArg::Cpu => Backend::Cpu,
            BackendArg::Gpu => Backend::Gpu,
        },
        precision: match a.precision {
            PrecisionArg::F32 => Precision::F32,
            PrecisionArg::F64 => Precision::F64,
        },
        terms: a.terms.map(usize::from),
        expansion: match a.expansion {
            ExpansionArg::Chebyshev => Expansion::Chebyshev,
            ExpansionArg::Taylor => Expansion::Taylor,
        },
    };
    if let (Backend::Gpu, Some(n)) = (opts.backend, opts.terms) {
        if !airlight_shaders::targets::NODE_COUNTS.contains(&n) {
            eprintln!("airlight: --terms {n} with --backend gpu: the shaders are emitted with 8 or 12 nodes per panel");
            return ExitCode::from(2);
        }
    }
    let stdin = std::io::stdin();
    let stdout = std::io::stdout();
    let result = match opts.backend {
        Backend::Gpu => eval::run_gpu(stdin.lock(), std::io::BufWriter::new(stdout.lock()), &opts),
        Backend::Cpu => eval::run(stdin.lock(), std::io::BufWriter::new(stdout.lock()), &opts),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(eval::EvalError::Output(e)) => output_failed(&e),
        Err(e) => {
            eprintln!("airlight: {e}");
            ExitCode::from(1)
        }
    }
}

fn cmd_emit(a: EmitArgs, check_only: bool) -> ExitCode {
    let mut opts = EmitOptions { terms: a.terms.iter().map(|t| t.count()).collect(), ..EmitOptions::default() };
    if let Some(tolerance) = a.tolerance {
        opts.tolerance = tolerance;
    }
    if !a.targets.is_empty() {
        match a.targets.iter().map(|t| Target::parse(t)).collect::<Result<Vec<_>, _>>() {
            Ok(t) => opts.targets = t,
            Err(e) => return error_line(&e),
        }
    }
    let dir = a.out.unwrap_or_else(targets::default_out_dir);
    if check_only {
        match targets::check(&dir, &opts) {
            Ok(problems) if problems.is_empty() => {
                println!("{}: up to date", dir.display());
                ExitCode::SUCCESS
            }
            Ok(problems) => {
                for p in &problems {
                    println!("{p}");
                }
                eprintln!("airlight: {} is stale ({} files); run `airlight emit`", dir.display(), problems.len());
                ExitCode::from(1)
            }
            Err(e) => error_line(&e),
        }
    } else {
        match targets::emit(&dir, &opts) {
            Ok(files) => {
                println!("wrote {} files to {}", files.len(), dir.display());
                ExitCode::SUCCESS
            }
            Err(e) => error_line(&e),
        }
    }
}

/// One error line; usage errors exit 2, everything else 1.
fn error_line(e: &targets::EmitError) -> ExitCode {
    eprintln!("airlight: {e}");
    match e {
        targets::EmitError::Usage(_) => ExitCode::from(2),
        _ => ExitCode::from(1),
    }
}

fn cmd_verify(a: VerifyArgs) -> ExitCode {
    let (cases, terms) = (a.cases as usize, a.terms.count());
    match airlight_codegen::verify::verify(cases, terms) {
        Ok(r) => {
            println!("adapter:            {}", r.adapter);
            println!("cases:              {} ({} terms)", r.cases, terms);
            println!("difference (of scale) to the f32 CPU kernel: max {:.2e}, median {:.2e}", r.max_diff, r.median_diff);
            println!("NaN/Inf:            {}", r.non_finite);
            println!("status mismatches:  {}", r.status_mismatches);
            println!("tolerance:          9·noise + 2e-4·scale (noise: f32 spread over one-ulp input changes); largest excess {:.2e}", r.max_excess);
            println!("verdict:            {}", if r.pass() { "PASS" } else { "FAIL" });
            if r.pass() { ExitCode::SUCCESS } else { ExitCode::from(1) }
        }
        Err(e) => {
            eprintln!("airlight: {e}");
            ExitCode::from(1)
        }
    }
}

fn cmd_render(a: RenderArgs) -> ExitCode {
    use airlight_codegen::render::{self, Image};
    use std::time::Instant;
    let scenes: Vec<&str> = if a.scene == "all" { render::SCENES.to_vec() } else { render::SCENES.iter().copied().filter(|n| *n == a.scene).collect() };
    let (size, out) = (a.size, a.out);
    let all = a.backend.contains(&RenderBackend::All);
    let has = |b: RenderBackend| all || a.backend.contains(&b);
    let (cpu, gpu, reference) = (has(RenderBackend::Cpu), has(RenderBackend::Gpu), has(RenderBackend::Reference));
    if let Err(e) = std::fs::create_dir_all(&out) {
        eprintln!("airlight: {}: {e}", out.display());
        return ExitCode::from(1);
    }
    let mut device = None;
    if gpu {
        match airlight_shaders::gpu::Gpu::new() {
            Ok(g) => device = Some(g),
            Err(e) if all => eprintln!("airlight: warning: skipping the gpu backend: {e}"),
            Err(e) => {
                eprintln!("airlight: {e}");
                return ExitCode::from(1);
            }
        }
    }
    let save = |name: &str, what: &str, rgb: &[u8]| -> Result<(), String> {
        let path = out.join(format!("{name}_{what}.png"));
        render::write_png(&path, size.0, size.1, rgb)
    };
    let prepared = device.as_ref().map(|g| {
        let start = Instant::now();
        let p = g.prepare(airlight_shaders::gpu::Shader::Wgsl(airlight_shaders::targets::compute_wgsl(airlight::SHADER_NODES)));
        println!("gpu: {}, shader compiled in {:.2} s", g.describe(), start.elapsed().as_secs_f64());
        p
    });
    for name in scenes {
        let scene = render::scene_by_name(name, size.0, size.1).expect("known scene");
        let mut times = Vec::new();
        let mut timed = |label: &str, f: &mut dyn FnMut() -> Result<Image, String>| -> Result<Image, String> {
            let start = Instant::now();
            let img = f()?;
            times.push(format!("{label} {:.2} s", start.elapsed().as_secs_f64()));
            save(name, label, &render::tone_map(&img, scene.exposure))?;
            Ok(img)
        };
        let result = (|| -> Result<String, String> {
            let cpu_img = if cpu { Some(timed("cpu", &mut || Ok(render::render_cpu(&scene, true)))?) } else { None };
            let gpu_img = match &prepared {
                Some(p) => Some(timed("gpu", &mut || render::render_gpu(&scene, p, true))?),
                None => None,
            };
            let ref_img = if reference { Some(timed("reference", &mut || Ok(render::render_reference(&scene, true)))?) } else { None };
            let mut errors = Vec::new();
            if let Some(r) = &ref_img {
                let floor = render::error_floor(&scene);
                for (label, file, img) in [("cpu", "error", &cpu_img), ("gpu", "error_gpu", &gpu_img)] {
                    if let Some(img) = img {
                        let e = render::relative_errors(img, r, floor);
                        let s = render::error_stats(&e);
                        save(name, file, &render::heat_map(&e, size.0, size.1))?;
                        errors.push(format!("{label} max {:.1e} median {:.1e}", s.max, s.median));
                    }
                }
                if !errors.is_empty() {
                    errors.insert(0, format!("relative error vs reference (floor {floor:.1e})"));
                }
            }
            Ok(errors.join(", "))
        })();
        match result {
            Ok(errors) => {
                let sep = if errors.is_empty() { "" } else { "; " };
                println!("{name} {}x{}: {}{sep}{errors}", size.0, size.1, times.join(", "));
            }
            Err(e) => {
                eprintln!("airlight: {e}");
                return ExitCode::from(1);
            }
        }
    }
    println!(
        "wrote {} (heat maps: log10 relative error from {} to {})",
        out.display(),
        render::HEAT_LOG10_MIN,
        render::HEAT_LOG10_MAX
    );
    ExitCode::SUCCESS
}
