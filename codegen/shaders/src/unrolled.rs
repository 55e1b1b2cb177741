//! Straight-line WGSL for the panel arithmetic of a fixed node count: the loops over the
//! Legendre terms that `kernel/src/panels.rs` and `kernel/src/special/en.rs` run, written out
//! with literal indices and the kernel's tables as literals.
//!
//! Why: a private array indexed by a loop counter, or a constant table returned by a function
//! and indexed at run time, lives in per-invocation memory; with every index a literal the
//! compiler keeps the array in registers. On Mesa's lavapipe (LLVM, 8 lanes per core) the
//! rolled loops made an 8-node panel cost 5× a 4-node one (`cargo bench -p airlight-codegen
//! --bench gpu`, BENCHMARKS.md). Each generated statement performs the kernel's operation in
//! the kernel's order, so the arithmetic is the kernel's; only terms that are structurally
//! zero (a coefficient of 0 in a table, a degree not yet reached) are left out.

use std::fmt::Write as _;

/// `format!("{:?}", x as f32)`: the literal of a kernel constant rounded to the shader's f32.
fn lit(x: f64) -> String {
    format!("{:?}", x as f32)
}

/// Body of `airlight_legendre(g)`: the discrete transform (panels.rs `legendre`), row `k` the
/// weights of `g(x_j) ± g(−x_j)` (`+` for even `k`), summed over `j` in order.
pub fn legendre_body(terms: usize, transform: &[f64]) -> String {
    let half = terms / 2;
    let mut s = String::new();
    for j in 0..half {
        let _ = writeln!(s, "    let even{j} = g[{}] + g[{}];", 2 * j + 1, 2 * j);
        let _ = writeln!(s, "    let odd{j} = g[{}] - g[{}];", 2 * j + 1, 2 * j);
    }
    let rows: Vec<String> = (0..terms)
        .map(|k| {
            let pair = if k % 2 == 0 { "even" } else { "odd" };
            (0..half).map(|j| format!("{} * {pair}{j}", lit(transform[k * half + j]))).collect::<Vec<_>>().join(" + ")
        })
        .collect();
    let _ = write!(s, "    return array<f32, {terms}>(\n        {});", rows.join(",\n        "));
    s
}

/// The stored steps of Miller's backward recurrence (panels.rs `exp_legendre_moments`), orders
/// `terms − 1` down to 1: store `f_k`, step, and rescale everything stored when `cur` passes
/// 1e20.
pub fn miller_stored(terms: usize) -> String {
    let mut s = String::new();
    for k in (1..terms).rev() {
        let _ = writeln!(s, "        out[{k}] = cur;");
        let _ = writeln!(s, "        below = above + odd * inv * cur;");
        let _ = writeln!(s, "        odd -= 2.0;");
        let _ = writeln!(s, "        above = cur;");
        let _ = writeln!(s, "        cur = below;");
        let rescale: Vec<String> = (k..terms).map(|i| format!("out[{i}] *= 1.0e-20;")).collect();
        let _ = writeln!(s, "        if (cur > 1.0e20) {{ cur *= 1.0e-20; above *= 1.0e-20; {} }}", rescale.join(" "));
    }
    s
}

/// The upward recurrence `out[k+1] = out[k−1] − (2k+1)/λ·out[k]`, `k = 1 … terms − 2`.
pub fn moments_upward(terms: usize) -> String {
    let mut s = String::new();
    for k in 1..terms.saturating_sub(1) {
        let _ = writeln!(s, "        out[{}] = out[{}] - {}.0 / lambda * out[{k}];", k + 1, k - 1, 2 * k + 1);
    }
    s
}

/// `out[k] *= ±2` (`M_k = 2(−1)^k e^{−λ} i_k`).
pub fn moments_signs(terms: usize) -> String {
    (0..terms).map(|k| format!("out[{k}] *= {};", if k % 2 == 1 { "-2.0" } else { "2.0" })).collect::<Vec<_>>().join(" ")
}

/// Body of `airlight_legendre_to_monomial(c)` (panels.rs `legendre_to_monomial`): `hat[i] +=
/// c_k · 2^{−k}·LEGENDRE_MONOMIAL[k][i]`, `k` outer, the zero entries left out.
pub fn legendre_to_monomial_body(terms: usize, table: &[[i64; 16]]) -> String {
    let mut s = String::new();
    let _ = writeln!(s, "    var hat = airlight_zero_terms();");
    for (k, row) in table.iter().enumerate().take(terms) {
        for (i, &a) in row.iter().enumerate().take(k + 1) {
            if a != 0 {
                let _ = writeln!(s, "    hat[{i}] += c[{k}] * {};", lit(a as f64 / (1u64 << k) as f64));
            }
        }
    }
    let _ = write!(s, "    return hat;");
    s
}

/// The tail panel's change of variable `Σ hat_j ξ^j → Σ q_k u^k`, `ξ = αu + β`, by Horner's
/// scheme from the highest `j` (panels.rs `tail_panel`): after `t + 1` steps `q` has degree
/// `t`, so only `q[0..=t]` are formed.
pub fn monomial_shift(terms: usize) -> String {
    let mut s = String::new();
    for t in 0..terms {
        let j = terms - 1 - t;
        // next[i] = q[i−1]·α + q[i]·β (q[i] = 0 for i ≥ t), next[0] += hat[j]
        let mut entries: Vec<String> = Vec::new();
        for i in 0..terms {
            let shifted = (i > 0 && i - 1 < t).then(|| format!("q[{}] * alpha", i - 1));
            let kept = (i < t).then(|| format!("q[{i}] * beta"));
            let e = match (shifted, kept) {
                (Some(a), Some(b)) => format!("{a} + {b}"),
                (Some(a), None) => a,
                (None, Some(b)) => b,
                (None, None) => "0.0".to_string(),
            };
            entries.push(if i == 0 { if t == 0 { format!("hat[{j}]") } else { format!("{e} + hat[{j}]") } } else { e });
        }
        let _ = writeln!(s, "    q = array<f32, {terms}>({});", entries.join(", "));
    }
    s
}

/// The recurrences of `airlight_en_scaled` (special/en.rs `en_scaled`) over `count` orders,
/// written out with selects on the pivot: up from the pivot `s_{n+1} = (1 − x s_n)/n` (with the
/// kernel's `1/n` rounded to f32), then down to it `s_n = (1 − n s_{n+1})/x`.
pub fn en_scaled_recurrences(count: usize) -> String {
    let mut s = String::new();
    let _ = writeln!(s, "    out[0] = select(0.0, start, pivot == 1u);");
    for n in 1..count {
        let _ = writeln!(s, "    out[{n}] = select((1.0 - x * out[{}]) * {}, start, pivot == {}u);", n - 1, lit(1.0 / n as f64), n + 1);
    }
    for n in (1..count).rev() {
        let _ = writeln!(s, "    out[{}] = select(out[{}], (1.0 - {n}.0 * out[{n}]) * inv_x, {n}u < pivot);", n - 1, n - 1);
    }
    s
}

/// `E_n(0)` scaled: `+∞` (the largest float) for `n = 1`, `1/(n − 1)` above.
pub fn en_scaled_at_zero(count: usize) -> String {
    let mut s = String::from("out[0] = AIRLIGHT_FLT_MAX;");
    for n in 2..=count {
        let _ = write!(s, " out[{}] = {};", n - 1, lit(1.0 / (n - 1) as f64));
    }
    s
}

/// Writes out the template's `@EACH_TERM@ statement` lines (`@EACH_TERM_FROM_1@`: from `k = 1`)
/// once per term `k < terms`, with `{k}` the index, `{k1}` the index `k + 1` and `{kf}` `k` as
/// an f32 literal: a loop over the terms without a run-time index.
pub fn expand_each_term(source: &str, terms: usize) -> String {
    let mut out = String::with_capacity(source.len());
    for line in source.lines() {
        let trimmed = line.trim_start();
        let indent = &line[..line.len() - trimmed.len()];
        let (from, stmt) = if let Some(rest) = trimmed.strip_prefix("@EACH_TERM_FROM_1@") {
            (1, rest.trim_start())
        } else if let Some(rest) = trimmed.strip_prefix("@EACH_TERM@") {
            (0, rest.trim_start())
        } else {
            out.push_str(line);
            out.push('\n');
            continue;
        };
        for k in from..terms {
            let _ = writeln!(out, "{indent}{}", stmt.replace("{k1}", &(k + 1).to_string()).replace("{kf}", &format!("{k}.0")).replace("{k}", &k.to_string()));
        }
    }
    out
}

/// The field of panel `i` in `AirlightPanelList` (letters: naga renames names ending in a
/// digit).
fn list_field(i: usize) -> String {
    format!("panel_{}", (b'a' + i as u8) as char)
}

/// The fields of `AirlightPanelList`, `panels` of them.
///
/// # Panics
/// Beyond 26 panels (one letter each).
pub fn list_fields(panels: usize) -> String {
    assert!(panels <= 26, "at most 26 listed panels");
    (0..panels).map(|i| format!("    {}: vec4<f32>,\n", list_field(i))).collect()
}

/// The cases of `airlight_list_get`: panel `i`'s field (the last for any larger `i`).
pub fn list_get(panels: usize) -> String {
    let mut s = String::new();
    for i in 0..panels {
        let case = if i + 1 == panels { "default".to_string() } else { format!("case {i}u") };
        let _ = writeln!(s, "        {case}: {{ return l.{}; }}", list_field(i));
    }
    s
}

/// The cases of `airlight_list_set` (indices beyond the list write nothing).
pub fn list_set(panels: usize) -> String {
    let mut s = String::new();
    for i in 0..panels {
        let _ = writeln!(s, "        case {i}u: {{ (*l).{} = v; }}", list_field(i));
    }
    s.push_str("        default: {}\n");
    s
}

/// The body of `airlight_list_scan`: panel by panel while `i < count`, the sums and the first
/// largest error (extended.rs `adaptive`'s scan, in its order).
pub fn list_scan(panels: usize) -> String {
    let mut s = String::new();
    for i in 0..panels {
        let f = list_field(i);
        let _ = writeln!(s, "    if (count > {i}u) {{");
        let _ = writeln!(s, "        r.total += l.{f}.z;");
        let _ = writeln!(s, "        r.errors += l.{f}.w;");
        let _ = writeln!(s, "        if (l.{f}.w > worst_error) {{ r.worst = {i}u; worst_error = l.{f}.w; }}");
        let _ = writeln!(s, "    }}");
    }
    s
}

/// A Gauss–Legendre rule written out: `template` once per node, in the kernel's order
/// (`area/outer.rs` `each_node`: for each pair of its positive half `(x, w)`, `−x` then `+x`),
/// with `@K@` the node's index, `@NODE@` its point `c ∓ x * hw` on the panel `[c − hw, c + hw]`
/// and `@W@` its weight on `[−1, 1]`.
pub fn gauss_lines(half: &[(f64, f64)], template: &str) -> String {
    let mut s = String::new();
    for (i, &(x, w)) in half.iter().enumerate() {
        for (j, sign) in ['-', '+'].into_iter().enumerate() {
            let node = format!("c {sign} {} * hw", lit(x));
            s.push_str(&template.replace("@K@", &(2 * i + j).to_string()).replace("@NODE@", &node).replace("@W@", &lit(w)));
        }
    }
    s
}

/// The steps of `c^e` by repeated squaring for exponents below `2^bits`, in the order of Rust's
/// `powi` (compiler-rt `__powisf2`: multiply where the exponent's low bit is set, halve it,
/// square), on the WGSL variables `e`, `base` and `acc`.
pub fn power_steps(bits: u32) -> String {
    (0..bits).map(|_| "    if ((e & 1u) != 0u) { acc *= base; }\n    e = e >> 1u;\n    base *= base;\n").collect()
}
