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

    emit    Write the shaders (compute entry point and include library, per target and term
            count) through naga into DIR (default: the workspace's shaders-out/). Everything
            is rendered and validated before anything is written.

    check   Exit 1 and list the stale, missing or unexpected files when DIR (default
            shaders-out/) is not what `emit` would write now.

    verify  Run the CPU/shader agreement check on this machine's GPU: N scenes (default 10000)
            through the committed compute shader, compared with the f32 CPU kernel; prints
            the adapter, cases, max/median difference, NaN count and a PASS/FAIL verdict
            (exit 1 on FAIL).

OPTIONS (eval):
    --backend cpu|gpu                CPU kernel (default) or the emitted compute shader through
                                     wgpu on this machine's GPU (f32; --precision and
                                     --expansion do not apply)
    --precision f32|f64              kernel precision (default f64)
    --terms 4|6                      expansion terms (default 6; shaders use 4)
    --expansion chebyshev|taylor     polynomial expansion (default chebyshev)
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
                "4" => Ok(opts.terms = 4),
                "6" => Ok(opts.terms = 6),
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
