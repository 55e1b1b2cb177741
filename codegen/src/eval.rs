//! `airlight eval`: JSON-lines scene records in, one JSON line per record out, in order.

use crate::scene_json::{parse_line, SceneRecord};
use airlight::{Expansion, Real, Scene};
use std::io::{BufRead, Write};

/// Evaluation precision.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Precision {
    /// `f32` kernel.
    F32,
    /// `f64` kernel.
    F64,
}

/// Options of `airlight eval`.
#[derive(Clone, Copy, Debug)]
pub struct EvalOptions {
    /// Kernel precision.
    pub precision: Precision,
    /// Expansion terms: 4 or 6.
    pub terms: usize,
    /// Expansion kind.
    pub expansion: Expansion,
}

impl Default for EvalOptions {
    fn default() -> Self {
        EvalOptions { precision: Precision::F64, terms: 6, expansion: Expansion::Chebyshev }
    }
}

/// `L_m` of a parsed record on the CPU kernel.
pub fn in_scatter<T: Real>(rec: &SceneRecord<T>, terms: usize, expansion: Expansion) -> T {
    match Scene::new(rec.ray, rec.light, rec.medium, rec.phase) {
        Ok(s) => match terms {
            4 => s.in_scatter_with::<4>(expansion),
            _ => s.in_scatter_with::<6>(expansion),
        },
        Err(_) => T::nan(),
    }
}

/// Formats a result as its output line: `{"in_scatter": x}` with the shortest representation
/// that parses back to the same value of the evaluation precision, `"inf"` for `+∞`.
pub fn format_value<T: Real>(x: T) -> String {
    if x == T::infinity() {
        return "{\"in_scatter\":\"inf\"}".to_string();
    }
    if !x.is_finite() {
        return "{\"error\":\"internal: the kernel produced a non-finite value\"}".to_string();
    }
    // f32 Display is the shortest round-trip representation of the f32 value; likewise f64.
    format!("{{\"in_scatter\":{:?}}}", x)
}

/// An error line naming the input line (1-based) and the field.
pub fn format_error(line_no: usize, message: &str) -> String {
    serde_json::json!({ "error": format!("line {line_no}: {message}") }).to_string()
}

fn eval_line<T: Real>(line: &str, line_no: usize, opts: &EvalOptions) -> String {
    match parse_line::<T>(line) {
        Ok(rec) => format_value(in_scatter(&rec, opts.terms, opts.expansion)),
        Err(e) => format_error(line_no, &e.to_string()),
    }
}

/// Runs `eval` over `input`, writing one line per non-empty input line to `out`.
pub fn run(input: impl BufRead, mut out: impl Write, opts: &EvalOptions) -> std::io::Result<()> {
    for (i, line) in input.lines().enumerate() {
        let line = line?;
        if line.trim().is_empty() {
            continue;
        }
        let result = match opts.precision {
            Precision::F32 => eval_line::<f32>(&line, i + 1, opts),
            Precision::F64 => eval_line::<f64>(&line, i + 1, opts),
        };
        writeln!(out, "{result}")?;
    }
    out.flush()
}
