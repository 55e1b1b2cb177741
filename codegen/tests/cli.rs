//! The `airlight` command line as a user meets it: per-command help, `--version`, `--opt=value`
//! spellings, and `eval` in a pipeline whose reader stops early.

use std::io::{BufRead, BufReader, Write};
use std::process::{Command, Stdio};

fn airlight() -> Command {
    Command::new(env!("CARGO_BIN_EXE_airlight"))
}

fn output(args: &[&str]) -> (bool, String, String) {
    let o = airlight().args(args).output().expect("airlight runs");
    (o.status.success(), String::from_utf8_lossy(&o.stdout).into_owned(), String::from_utf8_lossy(&o.stderr).into_owned())
}

#[test]
fn every_command_has_its_own_help_and_the_tool_a_version() {
    let (ok, version, _) = output(&["--version"]);
    assert!(ok && version.trim() == format!("airlight {}", env!("CARGO_PKG_VERSION")), "{version}");
    let mut pages = Vec::new();
    for cmd in ["eval", "emit", "check", "verify", "render"] {
        let (ok, page, err) = output(&[cmd, "--help"]);
        assert!(ok, "{cmd} --help failed: {err}");
        assert!(page.contains(&format!("Usage: airlight {cmd}")), "{cmd}: {page}");
        pages.push(page);
    }
    pages.dedup();
    assert_eq!(pages.len(), 5, "two commands share a help page");
}

#[test]
fn options_take_both_spellings_and_bad_values_are_named() {
    let line = r#"{"ray": {"origin": [0,0,0], "dir": [1,0,0], "t_max": 25}, "medium": {"sigma_s": 0.08, "sigma_t": 0.1}, "light": {"position": [5,1,0], "intensity": 100}}"#;
    let run = |args: &[&str]| {
        let mut child = airlight().args(args).stdin(Stdio::piped()).stdout(Stdio::piped()).stderr(Stdio::piped()).spawn().unwrap();
        // a rejected option ends the tool before it reads: the write may meet a closed pipe
        let _ = child.stdin.take().unwrap().write_all(line.as_bytes());
        child.wait_with_output().unwrap()
    };
    let a = run(&["eval", "--terms=4", "--precision=f32"]);
    let b = run(&["eval", "--terms", "4", "--precision", "f32"]);
    assert!(a.status.success() && a.stdout == b.stdout && a.stdout.starts_with(b"{\"in_scatter\":"), "{a:?}");
    let bad = run(&["eval", "--terms", "0"]);
    assert_eq!(bad.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&bad.stderr).contains("--terms"), "{bad:?}");
}

/// `airlight eval < big | head -1`: the reader closes the pipe after one line; the tool stops
/// quietly with exit 0 (no "Broken pipe" message), and it wrote that first line before reading
/// the rest of its input (line by line, as a co-process needs).
#[test]
fn eval_answers_line_by_line_and_ends_quietly_on_a_closed_pipe() {
    let line = r#"{"ray": {"origin": [0,0,0], "dir": [1,0,0], "t_max": 25}, "medium": {"sigma_s": 0.08, "sigma_t": 0.1}, "light": {"position": [5,1,0], "intensity": 100}}"#;
    let mut child = airlight().arg("eval").stdin(Stdio::piped()).stdout(Stdio::piped()).stderr(Stdio::piped()).spawn().unwrap();
    let mut stdin = child.stdin.take().unwrap();
    let mut stdout = BufReader::new(child.stdout.take().unwrap());
    // co-process: one line in, its answer out, with the input still open
    writeln!(stdin, "{line}").unwrap();
    stdin.flush().unwrap();
    let mut first = String::new();
    stdout.read_line(&mut first).unwrap();
    assert!(first.starts_with("{\"in_scatter\":"), "{first}");
    // the reader goes away; more input follows
    drop(stdout);
    for _ in 0..10_000 {
        if writeln!(stdin, "{line}").is_err() {
            break;
        }
    }
    drop(stdin);
    let out = child.wait_with_output().unwrap();
    assert_eq!(out.status.code(), Some(0), "stderr: {}", String::from_utf8_lossy(&out.stderr));
    assert!(out.stderr.is_empty(), "stderr: {}", String::from_utf8_lossy(&out.stderr));
}

/// `--terms` takes every count the kernel compiles (1 … 16) on the CPU and the emitted ones (4,
/// 6) on the GPU; a record's `"id"` comes back first in its answer, error lines included.
#[test]
fn every_term_count_and_ids_echoed() {
    let good = r#"{"id": "lamp-3", "ray": {"origin": [0,0,0], "dir": [1,0,0], "t_max": 25}, "medium": {"sigma_s": 0.08, "sigma_t": 0.1}, "light": {"position": [5,1,0], "intensity": 100}, "phase": {"kind": "henyey_greenstein", "g": 0.5}}"#;
    let bad = r#"{"id": 17, "ray": {"origin": [0,0,0], "dir": [1,0,0], "tmax": 25}}"#;
    let run = |args: &[&str]| {
        let mut child = airlight().args(args).stdin(Stdio::piped()).stdout(Stdio::piped()).stderr(Stdio::piped()).spawn().unwrap();
        // a rejected option ends the tool before it reads: the write may meet a closed pipe
        let _ = child.stdin.take().unwrap().write_all(format!("{good}\n{bad}\n").as_bytes());
        child.wait_with_output().unwrap()
    };
    let mut values = Vec::new();
    for terms in 1..=16 {
        let o = run(&["eval", &format!("--terms={terms}")]);
        let out = String::from_utf8_lossy(&o.stdout);
        let lines: Vec<&str> = out.lines().collect();
        assert!(o.status.success() && lines.len() == 2, "--terms {terms}: {out}");
        let v: serde_json::Value = serde_json::from_str(lines[0]).unwrap();
        assert_eq!(v["id"], "lamp-3", "{}", lines[0]);
        values.push(v["in_scatter"].as_f64().unwrap_or_else(|| panic!("--terms {terms}: {}", lines[0])));
        assert!(lines[1].starts_with(r#"{"id":17,"error":"line 2: ray.tmax"#), "{}", lines[1]);
    }
    // a gentle scene: the fixed method converges with the term count
    assert!((values[15] - values[11]).abs() < 1e-6 * values[15], "{values:?}");
    let o = run(&["eval", "--terms", "17"]);
    assert!(!o.status.success() && String::from_utf8_lossy(&o.stderr).contains("17 is not in 1..=16"));
    let o = run(&["eval", "--terms", "5", "--backend", "gpu"]);
    assert!(!o.status.success() && String::from_utf8_lossy(&o.stderr).contains("8 or 12 nodes"), "{}", String::from_utf8_lossy(&o.stderr));
}
