//! The `airlight` command: evaluate scenes, emit and check shaders.

use airlight::Expansion;
use airlight_codegen::eval::{self, EvalOptions, Precision};
use std::process::ExitCode;

const HELP: &str = "\
airlight — analytic fog glow (single-scattered air-light) of point and spot lights

USAGE:
    airlight eval [--backend cpu|gpu] [--precision f32|f64] [--terms 4|6] [--expansion chebyshev|taylor]
    airlight emit [--out DIR] [--terms 4|6|4,6] [--targets wgsl,glsl,spirv,hlsl,msl]
    airlight check [--dir DIR] [--terms ...] [--targets ...]
    airlight verify [--cases N] [--terms 4|6]
    airlight render [--scene lighthouse|road|stage|bench|all] [--size WxH] [--out DIR]
                    [--backend cpu|gpu|reference|all]
    airlight --help

COMMANDS:
    eval    Read scene records as JSON lines on stdin, write one JSON line per record on
            stdout, in input order: {\"in_scatter\": L} (\"inf\" for +infinity, when the light
            lies exactly on the segment) or {\"error\": \"line N: field: problem\"}. A bad line
            does not stop the others. Blank lines are skipped.

            Record: {\"ray\": {\"origin\": [x,y,z], \"dir\": [x,y,z], \"t_min\": 0, \"t_max\": 25 | null},
                     \"medium\": {\"sigma_s\": 0.08, \"sigma_t\": 0.1},
                     \"light\": {\"position\": [x,y,z], \"intensity\": 100,
                               \"distribution\": {\"kind\": \"isotropic\" | \"two_lobed\" (axis, power)
                                                | \"spot\" (axis, cos_inner, cos_outer)}},
                     \"phase\": {\"kind\": \"isotropic\" | \"rayleigh\" | \"henyey_greenstein\" (g)
                               | \"schlick\" (k) | \"cornette_shanks\" (g)
                               | \"two_lobe_henyey_greenstein\" (g1, g2, w)}}
            t_max null means +infinity; unknown fields are ignored.

    emit    Write the shaders (compute entry point and include library, per target and node
            count) through naga into DIR (default: the workspace's shaders-out/). Everything
            is rendered and validated before anything is written.

    check   Exit 1 and list the stale, missing or unexpected files when DIR (default
            shaders-out/) is not what `emit` would write now.

    verify  Run the CPU/shader agreement check on this machine's GPU: N scenes (default 10000)
            through the committed compute shader, compared with the f32 CPU kernel; prints
            the adapter, cases, max/median difference, NaN count and a PASS/FAIL verdict
            (exit 1 on FAIL).

    render  Render the pictures of issue 5 to PNG: a lighthouse with a two-lobed beam in thick
            brume, a foggy road with headlights and a streetlamp, a stage under three coloured
            spotlights, a park bench in Rayleigh mist. Writes DIR/<scene>_<backend>.png per
            backend — cpu (the f64 kernel's default path), gpu (the committed WGSL compute
            shader through wgpu, f32, 4 nodes per panel), reference (brute-force adaptive quadrature of
            the integral, no closed forms) — and, with the reference, error heat maps
            DIR/<scene>_error.png (cpu) and DIR/<scene>_error_gpu.png (shader): per-pixel
            relative error against the reference, log10 scale from 1e-7 (black) through blue,
            green, yellow to 1e-1 (red), with a colour bar along the bottom. Prints one summary
            line per scene (times, max/median error); progress on stderr for renders that take
            more than a second.

OPTIONS (render):
    --scene NAME|all                 lighthouse, road, stage, bench or all (default all)
    --size WxH                       image size in pixels (default 480x270)
    --out DIR                        output directory, created if missing (default renders)
    --backend cpu|gpu|reference|all  one backend, a comma list, or all (default all); with
                                     all, a machine without a GPU adapter skips gpu with a
                                     warning

OPTIONS (eval):
    --backend cpu|gpu                CPU kernel (default) or the emitted compute shader through
                                     wgpu on this machine's GPU (f32; --precision and
                                     --expansion do not apply)
    --precision f32|f64              kernel precision (default f64)
    --terms 4|6                      CPU: the paper's fixed-cost method with this many
                                     expansion terms (default: neither — the kernel's
                                     error-controlled panels, within 1e-10 in f64 and 1e-4 in
                                     f32 of max(|exact|, tau·scale)); GPU: the shader with this
                                     many nodes per panel (default 4)
    --expansion chebyshev|taylor     polynomial expansion of --terms (default chebyshev)
";

fn fail(msg: &str) -> ExitCode {
    eprintln!("airlight: {msg}");
    eprintln!("Try 'airlight --help'.");
    ExitCode::from(2)
}

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let Some(cmd) = args.first() else {
        print!("{HELP}");
        return ExitCode::from(2);
    };
    match cmd.as_str() {
        "--help" | "-h" | "help" => {
            print!("{HELP}");
            ExitCode::SUCCESS
        }
        "eval" => cmd_eval(&args[1..]),
        "emit" => cmd_emit(&args[1..], false),
        "check" => cmd_emit(&args[1..], true),
        "verify" => cmd_verify(&args[1..]),
        "render" => cmd_render(&args[1..]),
        other => fail(&format!("unknown command '{other}'")),
    }
}

fn cmd_eval(args: &[String]) -> ExitCode {
    let mut opts = EvalOptions::default();
    let mut it = args.iter();
    while let Some(a) = it.next() {
        let mut value = |name: &str| it.next().cloned().ok_or_else(|| format!("{name} needs a value"));
        let r: Result<(), String> = match a.as_str() {
            "--help" | "-h" => {
                print!("{HELP}");
                return ExitCode::SUCCESS;
            }
            "--backend" => value("--backend").and_then(|v| match v.as_str() {
                "cpu" => Ok(opts.backend = eval::Backend::Cpu),
                "gpu" => Ok(opts.backend = eval::Backend::Gpu),
                _ => Err(format!("--backend must be cpu or gpu, not '{v}'")),
            }),
            "--precision" => value("--precision").and_then(|v| match v.as_str() {
                "f32" => Ok(opts.precision = Precision::F32),
                "f64" => Ok(opts.precision = Precision::F64),
                _ => Err(format!("--precision must be f32 or f64, not '{v}'")),
            }),
            "--terms" => value("--terms").and_then(|v| match v.as_str() {
                "4" => Ok(opts.terms = Some(4)),
                "6" => Ok(opts.terms = Some(6)),
                _ => Err(format!("--terms must be 4 or 6, not '{v}'")),
            }),
            "--expansion" => value("--expansion").and_then(|v| match v.as_str() {
                "chebyshev" => Ok(opts.expansion = Expansion::Chebyshev),
                "taylor" => Ok(opts.expansion = Expansion::Taylor),
                _ => Err(format!("--expansion must be chebyshev or taylor, not '{v}'")),
            }),
            other => Err(format!("unknown option '{other}' for eval")),
        };
        if let Err(e) = r {
            return fail(&e);
        }
    }
    let stdin = std::io::stdin();
    let stdout = std::io::stdout();
    if opts.backend == eval::Backend::Gpu {
        return match eval::run_gpu(stdin.lock(), std::io::BufWriter::new(stdout.lock()), &opts) {
            Ok(()) => ExitCode::SUCCESS,
            Err(e) => {
                eprintln!("airlight: {e}");
                ExitCode::from(1)
            }
        };
    }
    match eval::run(stdin.lock(), std::io::BufWriter::new(stdout.lock()), &opts) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => fail(&format!("I/O error: {e}")),
    }
}

fn cmd_emit(args: &[String], check_only: bool) -> ExitCode {
    use airlight_codegen::targets::{self, EmitOptions, Target};
    let mut opts = EmitOptions::default();
    let mut dir = targets::default_out_dir();
    let mut it = args.iter();
    while let Some(a) = it.next() {
        let mut value = |name: &str| it.next().cloned().ok_or_else(|| format!("{name} needs a value"));
        let r: Result<(), String> = match a.as_str() {
            "--help" | "-h" => {
                print!("{HELP}");
                return ExitCode::SUCCESS;
            }
            "--out" | "--dir" => value(a).map(|v| dir = v.into()),
            "--terms" => value("--terms").and_then(|v| {
                v.split(',')
                    .map(|t| t.trim().parse::<usize>().map_err(|_| format!("--terms: '{t}' is not a number")))
                    .collect::<Result<Vec<_>, _>>()
                    .map(|t| opts.terms = t)
            }),
            "--targets" => value("--targets").and_then(|v| {
                v.split(',').map(|t| Target::parse(t).map_err(|e| e.to_string())).collect::<Result<Vec<_>, _>>().map(|t| opts.targets = t)
            }),
            other => Err(format!("unknown option '{other}'")),
        };
        if let Err(e) = r {
            return fail(&e);
        }
    }
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
fn error_line(e: &airlight_codegen::targets::EmitError) -> ExitCode {
    eprintln!("airlight: {e}");
    match e {
        airlight_codegen::targets::EmitError::Usage(_) => ExitCode::from(2),
        _ => ExitCode::from(1),
    }
}

fn cmd_verify(args: &[String]) -> ExitCode {
    let (mut cases, mut terms) = (10_000usize, 4usize);
    let mut it = args.iter();
    while let Some(a) = it.next() {
        let v = it.next();
        match (a.as_str(), v) {
            ("--cases", Some(v)) => match v.parse() {
                Ok(n) if n > 0 => cases = n,
                _ => return fail(&format!("--cases must be a positive number, not '{v}'")),
            },
            ("--terms", Some(v)) if v == "4" || v == "6" => terms = v.parse().unwrap(),
            ("--terms", Some(v)) => return fail(&format!("--terms must be 4 or 6, not '{v}'")),
            (other, _) => return fail(&format!("unknown or incomplete option '{other}' for verify")),
        }
    }
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

fn cmd_render(args: &[String]) -> ExitCode {
    use airlight_codegen::render::{self, Image};
    use std::time::Instant;
    let (mut scenes, mut size, mut out) = (render::SCENES.to_vec(), (480u32, 270u32), std::path::PathBuf::from("renders"));
    let (mut cpu, mut gpu, mut reference, mut all) = (true, true, true, true);
    let mut it = args.iter();
    while let Some(a) = it.next() {
        let mut value = |name: &str| it.next().cloned().ok_or_else(|| format!("{name} needs a value"));
        let r: Result<(), String> = match a.as_str() {
            "--help" | "-h" => {
                print!("{HELP}");
                return ExitCode::SUCCESS;
            }
            "--scene" => value("--scene").and_then(|v| match v.as_str() {
                "all" => Ok(scenes = render::SCENES.to_vec()),
                s => match render::SCENES.iter().find(|n| **n == s) {
                    Some(n) => Ok(scenes = vec![*n]),
                    None => Err(format!("--scene must be lighthouse, road, stage, bench or all, not '{s}'")),
                },
            }),
            "--size" => value("--size").and_then(|v| {
                let parsed = v.split_once(['x', 'X']).and_then(|(w, h)| Some((w.parse::<u32>().ok()?, h.parse::<u32>().ok()?)));
                match parsed {
                    Some((w, h)) if w > 0 && h > 0 && w <= 8192 && h <= 8192 => Ok(size = (w, h)),
                    _ => Err(format!("--size must be WxH with 1..8192 pixels each, not '{v}'")),
                }
            }),
            "--out" => value("--out").map(|v| out = v.into()),
            "--backend" => value("--backend").and_then(|v| {
                (cpu, gpu, reference, all) = (false, false, false, false);
                for b in v.split(',') {
                    match b.trim() {
                        "cpu" => cpu = true,
                        "gpu" => gpu = true,
                        "reference" => reference = true,
                        "all" => (cpu, gpu, reference, all) = (true, true, true, true),
                        other => return Err(format!("--backend must be cpu, gpu, reference or all, not '{other}'")),
                    }
                }
                Ok(())
            }),
            other => Err(format!("unknown option '{other}' for render")),
        };
        if let Err(e) = r {
            return fail(&e);
        }
    }
    if let Err(e) = std::fs::create_dir_all(&out) {
        eprintln!("airlight: {}: {e}", out.display());
        return ExitCode::from(1);
    }
    let mut device = None;
    if gpu {
        match airlight_codegen::gpu::Gpu::new() {
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
        let p = g.prepare(airlight_codegen::gpu::Shader::Wgsl(airlight_codegen::eval::compute_wgsl(airlight::SHADER_TERMS)));
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
