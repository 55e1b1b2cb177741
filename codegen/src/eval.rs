//! `airlight eval`: JSON-lines scene records in, one JSON line per record out, in order.

use crate::scene_json::{parse_line_with_id, AnyRecord};
use airlight::record::SceneRecord;
use airlight::{Expansion, Real};
use std::io::{BufRead, Write};

/// Evaluation precision.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Precision {
    /// `f32` kernel.
    F32,
    /// `f64` kernel.
    F64,
}

/// Where records are evaluated.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Backend {
    /// The CPU kernel.
    Cpu,
    /// The emitted compute shader (shaders-out/wgsl) through wgpu, in f32.
    Gpu,
}

/// Options of `airlight eval`.
#[derive(Clone, Copy, Debug)]
pub struct EvalOptions {
    /// CPU kernel or GPU shader.
    pub backend: Backend,
    /// Kernel precision.
    pub precision: Precision,
    /// `None`: the kernel's default, error-controlled path ([`airlight::Scene::in_scatter`]); `Some(4 | 6)`:
    /// one expansion of that many terms per piece (the paper's fixed-cost method). The GPU
    /// backend runs the shader with 8 Gauss–Legendre nodes per panel unless 12 is asked for.
    pub terms: Option<usize>,
    /// Expansion kind.
    pub expansion: Expansion,
}

impl Default for EvalOptions {
    fn default() -> Self {
        EvalOptions { backend: Backend::Cpu, precision: Precision::F64, terms: None, expansion: Expansion::Chebyshev }
    }
}

/// `L_m` of a parsed record on the CPU kernel: the default path, or `terms` fixed terms
/// (1 … 16; NaN outside, and for a record the kernel rejects).
pub fn in_scatter<T: Real>(rec: &SceneRecord<T>, terms: Option<usize>, expansion: Expansion) -> T {
    match rec.scene() {
        Ok(s) => match terms {
            None => s.in_scatter(),
            Some(n) => s.in_scatter_with_terms(n, expansion).unwrap_or(T::nan()),
        },
        Err(_) => T::nan(),
    }
}

/// Formats a result as its output line: `{"in_scatter": x}` with the shortest representation
/// that parses back to the same value of the evaluation precision, `"inf"` for `+∞`.
pub fn format_value<T: Real>(x: T) -> String {
    format_named("in_scatter", x)
}

/// [`format_value`] under another key (`surface_air_light`).
pub fn format_named<T: Real>(key: &str, x: T) -> String {
    if x == T::infinity() {
        return format!("{{\"{key}\":\"inf\"}}");
    }
    if !x.is_finite() {
        return "{\"error\":\"internal: the kernel produced a non-finite value\"}".to_string();
    }
    // f32 Display is the shortest round-trip representation of the f32 value; likewise f64.
    format!("{{\"{key}\":{:?}}}", x)
}

/// An error line naming the input line (1-based) and the field.
pub fn format_error(line_no: usize, message: &str) -> String {
    serde_json::json!({ "error": format!("line {line_no}: {message}") }).to_string()
}

fn eval_line<T: Real>(line: &str, line_no: usize, opts: &EvalOptions) -> String {
    let (id, record) = parse_line_with_id::<T>(line);
    let answer = match record {
        Ok(AnyRecord::Point(rec)) => format_value(in_scatter(&rec, opts.terms, opts.expansion)),
        Ok(AnyRecord::Segment(_)) if opts.terms.is_some() => {
            format_error(line_no, "light.shape: a segment light has no fixed-term method (--terms is for point lights)")
        }
        Ok(AnyRecord::Segment(scene)) => format_value(scene.in_scatter()),
        Ok(AnyRecord::Area(_)) if opts.terms.is_some() => format_error(line_no, "light.shape: an area light has no fixed-term method (--terms is for point lights)"),
        Ok(AnyRecord::Area(scene)) => format_value(scene.in_scatter()),
        Ok(AnyRecord::Surface(_)) if opts.terms.is_some() => format_error(line_no, "surface: surface records have no fixed-term method (--terms is for point lights)"),
        Ok(AnyRecord::Surface(scene)) => format_named("surface_air_light", scene.air_light()),
        Err(e) => format_error(line_no, &e.to_string()),
    };
    with_id(id.as_ref(), answer)
}

/// The answer line with the record's `"id"` (any JSON value) echoed first:
/// `{"id":7,"in_scatter":…}`.
pub fn with_id(id: Option<&serde_json::Value>, answer: String) -> String {
    match id {
        Some(id) => format!("{{\"id\":{id},{}", &answer[1..]),
        None => answer,
    }
}

/// Why `eval` stopped early.
#[derive(Debug)]
pub enum EvalError {
    /// Reading the input failed.
    Input(std::io::Error),
    /// Writing the output failed (a closed pipe among others: the command line ends quietly
    /// on that one).
    Output(std::io::Error),
    /// The GPU backend could not run.
    Gpu(String),
}

impl std::fmt::Display for EvalError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            EvalError::Input(e) => write!(f, "reading the input: {e}"),
            EvalError::Output(e) => write!(f, "writing the output: {e}"),
            EvalError::Gpu(e) => write!(f, "{e}"),
        }
    }
}

impl std::error::Error for EvalError {}

/// The input's lines, numbered from 1, each as its text or as the error line it gets: every
/// line (up to `\n`, `\r\n` or the end of the input) is one record, so output lines pair with
/// input lines by position. A line that is not UTF-8 or holds only white space is an error
/// line of its own; the lines after it are read on.
struct Lines<R> {
    input: R,
    number: usize,
    bytes: Vec<u8>,
}

impl<R: BufRead> Lines<R> {
    fn new(input: R) -> Self {
        Lines { input, number: 0, bytes: Vec::new() }
    }

    /// The next line: `Ok(None)` at the end, `Ok(Some((n, Ok(text))))` or
    /// `Ok(Some((n, Err(error_line))))`.
    fn next_line(&mut self) -> Result<Option<(usize, Result<&str, String>)>, EvalError> {
        self.bytes.clear();
        if self.input.read_until(b'\n', &mut self.bytes).map_err(EvalError::Input)? == 0 {
            return Ok(None);
        }
        self.number += 1;
        let mut end = self.bytes.len();
        if self.bytes[..end].ends_with(b"\n") {
            end -= 1;
        }
        if self.bytes[..end].ends_with(b"\r") {
            end -= 1;
        }
        let n = self.number;
        let text = match std::str::from_utf8(&self.bytes[..end]) {
            Err(e) => Err(format_error(n, &format!("(record): not UTF-8 (invalid byte at offset {})", e.valid_up_to()))),
            Ok(t) if t.trim().is_empty() => Err(format_error(n, "(record): empty line (every line is one record)")),
            Ok(t) => Ok(t),
        };
        Ok(Some((n, text)))
    }
}

/// Runs `eval` on the GPU: every record is parsed and checked as on the CPU (bad lines get
/// the same error lines), the valid ones are packed and run through the compute shader in
/// one batch after the input ends — through the library's point-light entry
/// (`airlight_shaders::targets::point_compute_wgsl`) when every one is a point light, area lights
/// in a batch of their own through the area entry (`area_compute_wgsl`).
pub fn run_gpu(input: impl BufRead, mut out: impl Write, opts: &EvalOptions) -> Result<(), EvalError> {
    use airlight_shaders::layout::{pack, pack_area, pack_segment, pack_surface, unpack_result, RECORD_SIZE, RESULT_SIZE, STATUS_INFINITE, STATUS_OK};
    // per input line: its "id" and its error line, or the output key of a packed record and
    // whether it is in the area lights' batch
    let mut lines: Vec<(Option<serde_json::Value>, Result<(Option<&str>, bool), String>)> = Vec::new();
    let (mut records, mut area_records) = (Vec::new(), Vec::new());
    let mut points = 0usize;
    let mut input = Lines::new(input);
    while let Some((n, text)) = input.next_line()? {
        match text.map(parse_line_with_id::<f32>) {
            Ok((id, Ok(AnyRecord::Point(r)))) => {
                points += 1;
                records.extend_from_slice(&pack(&r.ray, &r.light, &r.medium, &r.phase));
                lines.push((id, Ok((None, false))));
            }
            Ok((id, Ok(AnyRecord::Segment(r)))) => {
                records.extend_from_slice(&pack_segment(&r));
                lines.push((id, Ok((None, false))));
            }
            Ok((id, Ok(AnyRecord::Area(r)))) => {
                area_records.extend_from_slice(&pack_area(&r));
                lines.push((id, Ok((None, true))));
            }
            Ok((id, Ok(AnyRecord::Surface(r)))) => match pack_surface(&r) {
                Some(record) => {
                    records.extend_from_slice(&record);
                    lines.push((id, Ok((Some("surface_air_light"), false))));
                }
                None => lines.push((
                    id,
                    Err(format_error(n, "surface: lights with an axis are evaluated on the CPU backend (the shader library has Lambertian and Phong surfaces lit by omni lights)")),
                )),
            },
            Ok((id, Err(e))) => lines.push((id, Err(format_error(n, &e.to_string())))),
            Err(e) => lines.push((None, Err(e))),
        }
    }
    // area lights through their own entry, the rest through the full entry — or, point lights
    // alone, the library's point entry, without the segment and surface loop
    let (mut results, mut area_results) = (Vec::new(), Vec::new());
    if !(records.is_empty() && area_records.is_empty()) {
        let gpu = airlight_shaders::gpu::Gpu::new().map_err(EvalError::Gpu)?;
        let terms = opts.terms.unwrap_or(airlight::SHADER_NODES);
        let run = |shader: &str, records: &[u8]| gpu.run(airlight_shaders::gpu::Shader::Wgsl(shader), records, true).map_err(EvalError::Gpu);
        if !area_records.is_empty() {
            area_results = run(&airlight_shaders::targets::area_compute_wgsl(terms), &area_records)?;
        }
        if !records.is_empty() && points * RECORD_SIZE == records.len() {
            results = run(&airlight_shaders::targets::point_compute_wgsl(terms), &records)?;
        } else if !records.is_empty() {
            results = run(airlight_shaders::targets::compute_wgsl(terms), &records)?;
        }
    }
    let (mut results, mut area_results) = (results.chunks(RESULT_SIZE), area_results.chunks(RESULT_SIZE));
    for (id, l) in lines {
        let text = match l {
            Err(e) => e,
            Ok((key, area)) => {
                let result = if area { area_results.next() } else { results.next() };
                let (v, status) = unpack_result(result.expect("one result per packed record"));
                let value = |x: f32| match key {
                    Some(key) => format_named(key, x),
                    None => format_value(x),
                };
                match status {
                    STATUS_OK => value(v),
                    STATUS_INFINITE => value(f32::INFINITY),
                    _ => "{\"error\":\"the shader rejected a record the CPU accepted\"}".to_string(),
                }
            }
        };
        writeln!(out, "{}", with_id(id.as_ref(), text)).map_err(EvalError::Output)?;
    }
    out.flush().map_err(EvalError::Output)
}

/// Runs `eval` over `input`: one output line per input line, each written and flushed as soon
/// as it is computed (so `eval` works as a co-process).
pub fn run(input: impl BufRead, mut out: impl Write, opts: &EvalOptions) -> Result<(), EvalError> {
    let mut input = Lines::new(input);
    while let Some((n, text)) = input.next_line()? {
        let result = match text {
            Err(e) => e,
            Ok(line) => match opts.precision {
                Precision::F32 => eval_line::<f32>(line, n, opts),
                Precision::F64 => eval_line::<f64>(line, n, opts),
            },
        };
        writeln!(out, "{result}").map_err(EvalError::Output)?;
        out.flush().map_err(EvalError::Output)?;
    }
    Ok(())
}
