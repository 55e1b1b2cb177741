// airlight — analytic single-scattered air-light of point and spot lights in a homogeneous
// medium (Pegoraro, Schott & Parker, Graphics Interface 2009), f32, @TERMS@ expansion terms.
//
// The single shader source of truth, mirroring the CPU kernel (crate `airlight`, kernel/src)
// module by module: special/ (exponential integrals) → expansion/ (Chebyshev) → integrals.rs
// (moments) → combined.rs (split at the light's foot) → geometry.rs, with phase.rs and light.rs.
// Every public name starts with `airlight_`. Loops have constant bounds only.

const AIRLIGHT_TERMS: u32 = @TERMS@u;
const AIRLIGHT_PI: f32 = 3.14159265358979;
const AIRLIGHT_EULER_GAMMA: f32 = 0.5772156649015329;
const AIRLIGHT_FLT_MAX: f32 = 3.40282347e38;
const AIRLIGHT_FLT_EPS: f32 = 1.1920929e-7;
const AIRLIGHT_LN_2: f32 = 0.6931472;
// Scratch size of the E_n and moment arrays: orders up to 3 + 2·5 (N_1 series) and N + 2.
const AIRLIGHT_SCRATCH: u32 = 16u;

/// Explicitly zeroed arrays (some HLSL front ends reject the zero-value cast naga would
/// otherwise write for an uninitialised `var`).
fn airlight_zero_terms() -> array<f32, AIRLIGHT_TERMS> {
    return array<f32, AIRLIGHT_TERMS>(@ZEROS_TERMS@);
}

fn airlight_zero_scratch() -> array<f32, AIRLIGHT_SCRATCH> {
    return array<f32, AIRLIGHT_SCRATCH>(0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0);
}

// Phase-function and light-distribution kinds (record fields `phase_kind`, `light_kind`).
const AIRLIGHT_PHASE_ISOTROPIC: u32 = 0u;
const AIRLIGHT_PHASE_RAYLEIGH: u32 = 1u;
const AIRLIGHT_PHASE_HENYEY_GREENSTEIN: u32 = 2u;
const AIRLIGHT_PHASE_SCHLICK: u32 = 3u;
const AIRLIGHT_PHASE_CORNETTE_SHANKS: u32 = 4u;
const AIRLIGHT_PHASE_TWO_LOBE_HG: u32 = 5u;
const AIRLIGHT_LIGHT_OMNI: u32 = 0u;
const AIRLIGHT_LIGHT_TWO_LOBED: u32 = 1u;
const AIRLIGHT_LIGHT_SPOT: u32 = 2u;

// Result status codes.
const AIRLIGHT_STATUS_OK: u32 = 0u;
const AIRLIGHT_STATUS_INVALID: u32 = 1u;
const AIRLIGHT_STATUS_INFINITE: u32 = 2u;

/// A scene: the kernel's Ray, PointLight, Medium and phase function in one struct.
struct AirlightScene {
    origin: vec3<f32>,
    t_min: f32,
    dir: vec3<f32>,
    /// Segment end; ignored when `t_max_infinite` is set.
    t_max: f32,
    light_position: vec3<f32>,
    intensity: f32,
    /// Light axis (two-lobed, spot).
    light_axis: vec3<f32>,
    /// two-lobed: power p (even); spot: cos_inner.
    light_param_a: f32,
    /// spot: cos_outer.
    light_param_b: f32,
    sigma_s: f32,
    sigma_t: f32,
    /// HG/Cornette–Shanks: g; Schlick: k; two-lobe HG: g1.
    phase_param_a: f32,
    /// two-lobe HG: g2.
    phase_param_b: f32,
    /// two-lobe HG: w.
    phase_param_c: f32,
    light_kind: u32,
    phase_kind: u32,
    /// bit 0: t_max is +∞.
    flags: u32,
}

/// `in_scatter` (L_m) and a status: OK, INVALID (value 0) or INFINITE (value FLT_MAX).
struct AirlightResult {
    in_scatter: f32,
    status: u32,
}

// ---------------------------------------------------------------- complex arithmetic
// (kernel/src/special/complex.rs)

fn airlight_cmul(a: vec2<f32>, b: vec2<f32>) -> vec2<f32> {
    return vec2<f32>(a.x * b.x - a.y * b.y, a.x * b.y + a.y * b.x);
}

/// a / b by Smith's algorithm.
fn airlight_cdiv(a: vec2<f32>, b: vec2<f32>) -> vec2<f32> {
    if (abs(b.x) >= abs(b.y)) {
        let r = b.y / b.x;
        let den = b.x + b.y * r;
        return vec2<f32>((a.x + a.y * r) / den, (a.y - a.x * r) / den);
    }
    let r = b.x / b.y;
    let den = b.x * r + b.y;
    return vec2<f32>((a.x * r + a.y) / den, (a.y * r - a.x) / den);
}

/// |z|, scaled by the larger part first: `length` may square its argument, and |z|² underflows
/// to 0 below |z| ≈ 1e-19 (num-complex's `norm` is a hypot; found by the shader fuzz target:
/// ln z = −∞ for z = 1.9e-37).
fn airlight_cabs(z: vec2<f32>) -> f32 {
    let m = max(abs(z.x), abs(z.y));
    if (m == 0.0) { return 0.0; }
    return m * length(z / m);
}

/// Principal square root (Kahan).
fn airlight_csqrt(z: vec2<f32>) -> vec2<f32> {
    if (z.x == 0.0 && z.y == 0.0) {
        return vec2<f32>(0.0, z.y);
    }
    let r = airlight_cabs(z);
    if (z.x >= 0.0) {
        let t = sqrt((r + z.x) * 0.5);
        return vec2<f32>(t, z.y / (t + t));
    }
    let t = sqrt((r - z.x) * 0.5);
    return vec2<f32>(abs(z.y) / (t + t), select(-t, t, z.y >= 0.0));
}

/// e^z for |Im z| ≤ 2.2 (the E1 series region).
fn airlight_cexp(z: vec2<f32>) -> vec2<f32> {
    let m = exp(z.x);
    let cs = airlight_cos_sin(z.y);
    return vec2<f32>(m * cs.x, m * cs.y);
}

/// ln z for Re z ≥ 0.
fn airlight_cln(z: vec2<f32>) -> vec2<f32> {
    // arg z for Re z ≥ 0 (all our arguments), from the accurate atan above
    var arg = 1.5707963267948966;
    if (z.x > 0.0) {
        arg = airlight_atan(abs(z.y) / z.x);
    }
    return vec2<f32>(log(airlight_cabs(z)), select(arg, -arg, z.y < 0.0));
}

// Vulkan allows atan 4096 ulp, sin/cos 2^-11 absolute and log 2^-21 absolute near 1 — far too
// loose where the moment recurrence amplifies the error of Q_0 — so these are computed here
// from + − × ÷ (correctly rounded or 2.5 ulp) only.

/// atan(x) for x ≥ 0 (Cephes atanf: reduction by π/2 and π/4, then a degree-9 odd
/// polynomial; ≈ 2 ulp).
fn airlight_atan(x: f32) -> f32 {
    var y = 0.0;
    var t = x;
    if (x > 2.414213562373095) {
        y = 1.5707963267948966;
        t = -1.0 / x;
    } else if (x > 0.4142135623730950) {
        y = 0.7853981633974483;
        t = (x - 1.0) / (x + 1.0);
    }
    let z = t * t;
    return y + ((((8.05374449538e-2 * z - 1.38776856032e-1) * z + 1.99777106478e-1) * z - 3.33329491539e-1) * z * t + t);
}

/// log(1 + x) for x ≥ 0: 2 atanh(x/(2+x)) by its series where x ≤ 1 (ratio s² ≤ 1/9, 9
/// terms), the built-in log above (where it is 3 ulp).
fn airlight_log1p(x: f32) -> f32 {
    if (x > 1.0) {
        return log(1.0 + x);
    }
    let s = x / (2.0 + x);
    let s2 = s * s;
    var sum = 0.0;
    for (var k = 0u; k < 9u; k++) {
        sum = sum * s2 + 1.0 / f32(2u * (8u - k) + 1u);
    }
    return 2.0 * s * sum;
}

/// (cos x, sin x) for |x| ≤ 2.2 by Taylor polynomials (degree 16/17, error < 2^-24 there).
fn airlight_cos_sin(x: f32) -> vec2<f32> {
    let z = x * x;
    var c = 0.0;
    var s = 0.0;
    for (var k = 0u; k < 9u; k++) {
        let n = 8u - k;
        // c_n = (−1)^n/(2n)!, s_n = (−1)^n/(2n+1)!; Horner from the top
        c = c * z;
        s = s * z;
        var fc = 1.0;
        for (var j = 1u; j <= 2u * n; j++) { fc *= f32(j); }
        let sign = select(1.0, -1.0, (n & 1u) == 1u);
        c += sign / fc;
        s += sign / (fc * f32(2u * n + 1u));
    }
    return vec2<f32>(c, s * x);
}

fn airlight_is_finite(x: f32) -> bool {
    return (bitcast<u32>(x) & 0x7f800000u) != 0x7f800000u;
}

// ---------------------------------------------------------------- exponential integrals
// (kernel/src/special/: series.rs, continued_fraction.rs, e1.rs, en.rs)

/// Ein(z) = Σ_{k≥1} (−1)^{k+1} z^k/(k·k!), 14 terms (A&S 5.1.11).
fn airlight_ein(z: vec2<f32>) -> vec2<f32> {
    var term = vec2<f32>(-1.0, 0.0);
    var sum = vec2<f32>(0.0, 0.0);
    for (var k = 1u; k <= 14u; k++) {
        let kf = f32(k);
        term = -airlight_cmul(term, z) / kf;
        sum += term / kf;
    }
    return sum;
}

/// (Ein(b) − Ein(a))/(b − a) by divided differences, 14 terms.
fn airlight_ein_divided_difference(a: vec2<f32>, b: vec2<f32>) -> vec2<f32> {
    var h = vec2<f32>(1.0, 0.0);
    var a_pow = vec2<f32>(1.0, 0.0);
    var fact = 1.0;
    var sign = 1.0;
    var sum = vec2<f32>(0.0, 0.0);
    for (var k = 1u; k <= 14u; k++) {
        let kf = f32(k);
        fact *= kf;
        sum += h * (sign / (kf * fact));
        a_pow = airlight_cmul(a_pow, a);
        h = airlight_cmul(h, b) + a_pow;
        sign = -sign;
    }
    return sum;
}

/// Power series inside the ellipse (Re z/1.3)² + (Im z/2.1)² < 1.
fn airlight_in_series_region(z: vec2<f32>) -> bool {
    let x = z.x * (1.0 / 1.3);
    let y = z.y * (1.0 / 2.1);
    return x * x + y * y < 1.0;
}

/// e^z E1(z) by the continued fraction (A&S 5.1.22) with the tail estimate; depth by |z|.
fn airlight_e1_scaled_cf(z: vec2<f32>) -> vec2<f32> {
    let ax = abs(z.x);
    let ay = abs(z.y);
    var r2 = 3.0e38;
    if (max(ax, ay) < 1.0e18) {
        r2 = ax * ax + ay * ay;
    }
    var depth = 2u;
    if (r2 < 9.0) { depth = 15u; } else if (r2 < 25.0) { depth = 10u; } else if (r2 < 100.0) { depth = 6u; } else if (r2 < 900.0) { depth = 3u; }
    let nf = f32(depth);
    let b = z + vec2<f32>(2.0 * nf + 1.0, 0.0);
    let q = airlight_cdiv(vec2<f32>(2.0 * (nf + 1.0), 0.0), b);
    var root = airlight_csqrt(vec2<f32>(1.0, 0.0) - airlight_cmul(q, q));
    if (root.x < 0.0) {
        root = -root;
    }
    var t = airlight_cmul(b, vec2<f32>(1.0, 0.0) + root) * 0.5;
    for (var i = 0u; i < 15u; i++) {
        if (i < depth) {
            let kf = f32(depth - i);
            t = z + vec2<f32>(2.0 * kf - 1.0, 0.0) - airlight_cdiv(vec2<f32>(kf * kf, 0.0), t);
        }
    }
    return airlight_cdiv(vec2<f32>(1.0, 0.0), t);
}

/// e^z E1(z) for Re z ≥ 0.
fn airlight_e1_scaled(z: vec2<f32>) -> vec2<f32> {
    if (airlight_in_series_region(z)) {
        let e1 = airlight_ein(z) - airlight_cln(z) - vec2<f32>(AIRLIGHT_EULER_GAMMA, 0.0);
        return airlight_cmul(e1, airlight_cexp(z));
    }
    return airlight_e1_scaled_cf(z);
}

/// e^x E_n(x) by its continued fraction, x outside the series region.
fn airlight_en_scaled_cf(x: f32, n: u32) -> f32 {
    var depth = 2u;
    if (x < 3.0) { depth = 15u; } else if (x < 5.0) { depth = 10u; } else if (x < 10.0) { depth = 6u; } else if (x < 30.0) { depth = 3u; }
    let nf = f32(n);
    let m = f32(depth);
    let b = x + nf + 2.0 * (m + 1.0);
    let a = (m + 2.0) * (nf + m + 1.0);
    let disc = 1.0 - 4.0 * a / (b * b);
    var t = b;
    if (disc > 0.0) {
        t = b * (1.0 + sqrt(disc)) * 0.5;
    }
    for (var i = 0u; i < 15u; i++) {
        if (i < depth) {
            let kf = f32(depth - i);
            t = x + nf + 2.0 * kf - (kf + 1.0) * (nf + kf) / t;
        }
    }
    return 1.0 / (x + nf - nf / t);
}

/// out[k] = e^x E_{k+1}(x), k < count ≤ AIRLIGHT_SCRATCH, x ≥ 0; recurrences away from the
/// pivot order n* ≈ x (Miller's rule).
fn airlight_en_scaled(x: f32, count: u32, out: ptr<function, array<f32, AIRLIGHT_SCRATCH>>) {
    if (x == 0.0) {
        // E_1(0) = +∞ (never used at x = 0), E_n(0) = 1/(n − 1)
        (*out)[0] = AIRLIGHT_FLT_MAX;
        for (var n = 2u; n <= AIRLIGHT_SCRATCH; n++) {
            (*out)[n - 1u] = 1.0 / f32(n - 1u);
        }
        return;
    }
    var pivot = 1u;
    if (airlight_in_series_region(vec2<f32>(x, 0.0))) {
        (*out)[0] = airlight_e1_scaled(vec2<f32>(x, 0.0)).x;
    } else {
        pivot = u32(clamp(ceil(x), 1.0, f32(count)));
        (*out)[pivot - 1u] = airlight_en_scaled_cf(x, pivot);
    }
    for (var n = 1u; n < AIRLIGHT_SCRATCH; n++) {
        if (n >= pivot && n < count) {
            (*out)[n] = (1.0 - x * (*out)[n - 1u]) / f32(n);
        }
    }
    for (var i = 1u; i < AIRLIGHT_SCRATCH; i++) {
        if (i < pivot) {
            let n = pivot - i;
            (*out)[n - 1u] = (1.0 - f32(n) * (*out)[n]) / x;
        }
    }
}

// ---------------------------------------------------------------- phase functions, lights
// (kernel/src/phase.rs, kernel/src/light.rs)

/// 1 + g² − 2gμ as two non-negative terms (phase.rs::hg_kernel): no cancellation at a peak.
fn airlight_hg_base(g: f32, mu: f32) -> f32 {
    if (g >= 0.0) {
        let a = 1.0 - g;
        return (1.0 - mu) * (g + g) + a * a;
    }
    let b = 1.0 + g;
    return (mu + 1.0) * -(g + g) + b * b;
}

fn airlight_hg(g: f32, mu: f32) -> f32 {
    let base = airlight_hg_base(g, mu);
    return (1.0 - g) * (1.0 + g) / (4.0 * AIRLIGHT_PI * base * sqrt(base));
}

/// P(μ), normalised over the sphere, μ = 1 forward.
fn airlight_phase(kind: u32, p0: f32, p1: f32, p2: f32, mu: f32) -> f32 {
    switch kind {
        case 1u: { return 3.0 / (16.0 * AIRLIGHT_PI) * (1.0 + mu * mu); }
        case 2u: { return airlight_hg(p0, mu); }
        case 3u: {
            let d = 1.0 - p0 * mu;
            return (1.0 - p0) * (1.0 + p0) / (4.0 * AIRLIGHT_PI * d * d);
        }
        case 4u: {
            let base = airlight_hg_base(p0, mu);
            return 3.0 * (1.0 - p0) * (1.0 + p0) * (1.0 + mu * mu) / (8.0 * AIRLIGHT_PI * (2.0 + p0 * p0) * base * sqrt(base));
        }
        case 5u: { return p2 * airlight_hg(p0, mu) + (1.0 - p2) * airlight_hg(p1, mu); }
        default: { return 1.0 / (4.0 * AIRLIGHT_PI); }
    }
}

/// D(c): omni 1, two-lobed c^p, spot smoothstep between cos_outer and cos_inner.
fn airlight_light(kind: u32, p0: f32, p1: f32, c: f32) -> f32 {
    switch kind {
        case 1u: {
            // c^p by repeated squaring, p ≤ 1024
            var base = c;
            var e = u32(p0);
            var acc = 1.0;
            for (var i = 0u; i < 11u; i++) {
                if ((e & 1u) == 1u) { acc *= base; }
                e = e >> 1u;
                base *= base;
            }
            return acc;
        }
        case 2u: {
            // an edge narrower than f32's epsilon is a step at its middle (light.rs)
            let width = p0 - p1;
            if (width <= AIRLIGHT_FLT_EPS) {
                return select(0.0, 1.0, c >= p1 + width * 0.5);
            }
            let x = clamp((c - p1) / width, 0.0, 1.0);
            return x * x * (3.0 - 2.0 * x);
        }
        default: { return 1.0; }
    }
}

// ---------------------------------------------------------------- the canonical problem
// (kernel/src/geometry.rs, kernel/src/combined.rs)

struct AirlightCanonical {
    h: f32,
    x_h: f32,
    d_el: f32,
    d_c: f32,
    t_lo: f32,
    t_hi: f32,
    t_hi_infinite: bool,
}

struct AirlightHalf {
    second: bool,
    big_h: f32,
    y_lo: f32,
    y_hi: f32,
    dy: f32,
    dv: f32,
    dv_infinite: bool,
}

/// F(y) = D(c(y))·P(μ(y)) on a half: μ = −σ(1−y²)/(1+y²), c = (σ d_el(1−y²) + 2 d_c y)/(1+y²).
fn airlight_integrand(s: AirlightScene, g: AirlightCanonical, sigma: f32, y: f32) -> f32 {
    let y2 = y * y;
    let inv = 1.0 / (1.0 + y2);
    let om = 1.0 - y2;
    let mu = -sigma * om * inv;
    let c = (sigma * g.d_el * om + 2.0 * g.d_c * y) * inv;
    return airlight_light(s.light_kind, s.light_param_a, s.light_param_b, c)
        * airlight_phase(s.phase_kind, s.phase_param_a, s.phase_param_b, s.phase_param_c, mu);
}

// ---------------------------------------------------------------- expansion
// (kernel/src/expansion/chebyshev.rs)

/// Local monomial coefficients a_k of F(y_c + s) ≈ Σ a_k s^k, interpolating at the Chebyshev
/// nodes of [y_c − r, y_c + r], with the rounding-noise floor of the kernel.
fn airlight_chebyshev(s: AirlightScene, g: AirlightCanonical, sigma: f32, y_c: f32, r: f32) -> array<f32, AIRLIGHT_TERMS> {
    let nf = f32(AIRLIGHT_TERMS);
    let theta = AIRLIGHT_PI / (nf + nf);
    let c2 = cos(theta + theta);
    var prev = cos(theta);
    var cur = prev;
    var xi = airlight_zero_terms();
    var values = airlight_zero_terms();
    for (var j = 0u; j < AIRLIGHT_TERMS; j++) {
        xi[j] = cur;
        let next = (c2 + c2) * cur - prev;
        prev = cur;
        cur = next;
        values[j] = airlight_integrand(s, g, sigma, y_c + r * xi[j]);
    }
    var cheb = airlight_zero_terms();
    for (var j = 0u; j < AIRLIGHT_TERMS; j++) {
        var t_prev = 1.0;
        var t_cur = xi[j];
        for (var k = 0u; k < AIRLIGHT_TERMS; k++) {
            var tk = t_cur;
            if (k == 0u) { tk = 1.0; }
            cheb[k] += values[j] * tk;
            if (k >= 1u) {
                let t_next = (xi[j] + xi[j]) * t_cur - t_prev;
                t_prev = t_cur;
                t_cur = t_next;
            }
        }
    }
    var scale_sum = 0.0;
    for (var k = 0u; k < AIRLIGHT_TERMS; k++) {
        cheb[k] *= 2.0 / nf;
        if (k == 0u) { cheb[k] *= 0.5; }
        scale_sum += abs(cheb[k]);
    }
    var t_km1 = airlight_zero_terms();
    var t_k = airlight_zero_terms();
    var hat = airlight_zero_terms();
    t_km1[0] = 1.0;
    t_k[1] = 1.0;
    hat[0] = cheb[0];
    for (var k = 1u; k < AIRLIGHT_TERMS; k++) {
        var t_next = airlight_zero_terms();
        for (var i = 0u; i < AIRLIGHT_TERMS; i++) {
            hat[i] += cheb[k] * t_k[i];
            var shifted = 0.0;
            if (i > 0u) { shifted = t_k[i - 1u]; }
            t_next[i] = shifted + shifted - t_km1[i];
        }
        t_km1 = t_k;
        t_k = t_next;
    }
    var amplification = 1.0;
    for (var k = 0u; k < AIRLIGHT_TERMS; k++) { amplification *= 2.41421356; }
    let noise = 4.0 * nf * AIRLIGHT_FLT_EPS * amplification * scale_sum;
    var a = airlight_zero_terms();
    var rk = 1.0;
    for (var k = 0u; k < AIRLIGHT_TERMS; k++) {
        if (k == 0u) {
            a[k] = hat[k];
        } else if (abs(hat[k]) > noise && rk > 0.0) {
            let ak = hat[k] / rk;
            if (airlight_is_finite(ak)) { a[k] = ak; }
        }
        rk *= r;
    }
    return a;
}

// ---------------------------------------------------------------- moments
// (kernel/src/integrals.rs)

/// Gauss–Legendre moments on a short sub-interval (route 1), 4 points.
fn airlight_moments_gauss(half: AirlightHalf) -> array<f32, AIRLIGHT_TERMS> {
    var m = airlight_zero_terms();
    let hw = half.dy * 0.5;
    let yc = half.y_lo + hw;
    let nodes = array<vec2<f32>, 4>(
        vec2<f32>(-0.8611363115940526, 0.3478548451374538), vec2<f32>(-0.3399810435848563, 0.6521451548625461),
        vec2<f32>(0.3399810435848563, 0.6521451548625461), vec2<f32>(0.8611363115940526, 0.3478548451374538));
    for (var j = 0u; j < 4u; j++) {
        let xi = nodes[j].x;
        let s = hw * xi;
        let y = yc + s;
        var dv = hw * (1.0 + xi);
        if (half.second) { dv = hw * (1.0 - xi) / (y * half.y_hi); }
        var p = nodes[j].y * hw * exp(-half.big_h * dv) / (1.0 + y * y);
        for (var k = 0u; k < AIRLIGHT_TERMS; k++) {
            m[k] += p;
            p *= s;
        }
    }
    return m;
}

/// [ln(v/|v − i|)] between v_s and v_e (v_e may be ∞).
fn airlight_n1_log_part(v_s: f32, v_e: f32, v_e_infinite: bool) -> f32 {
    var at_e = 0.0;
    if (!v_e_infinite) {
        let y_e = 1.0 / v_e;
        at_e = airlight_log1p(y_e * y_e);
    }
    let y_s = 1.0 / v_s;
    return -0.5 * (at_e - airlight_log1p(y_s * y_s));
}

/// T_n = y_hi^{n−1} s_n(H v_s) − e^{−HΔv} y_lo^{n−1} s_n(H v_e), out[n−1], 2 ≤ n ≤ count.
fn airlight_t_moments(half: AirlightHalf, count: u32, out: ptr<function, array<f32, AIRLIGHT_SCRATCH>>) {
    var s_s = airlight_zero_scratch();
    var s_e = airlight_zero_scratch();
    airlight_en_scaled(half.big_h / half.y_hi, count, &s_s);
    let far_end = half.y_lo > 0.0 && airlight_is_finite(half.big_h / half.y_lo);
    var decay = 0.0;
    if (far_end && !half.dv_infinite) {
        decay = exp(-half.big_h * half.dv);
        airlight_en_scaled(half.big_h / half.y_lo, count, &s_e);
    }
    var p_hi = half.y_hi;
    var p_lo = half.y_lo;
    for (var order = 2u; order < AIRLIGHT_SCRATCH; order++) {
        if (order <= count) {
            (*out)[order - 1u] = p_hi * s_s[order - 1u] - p_lo * s_e[order - 1u] * decay;
            p_hi *= half.y_hi;
            p_lo *= half.y_lo;
        }
    }
}

/// N_1 far from the foot (y ≤ 1/4): Σ_j (−1)^j T_{3+2j}, 6 terms.
fn airlight_n1_series(half: AirlightHalf) -> f32 {
    var t = airlight_zero_scratch();
    airlight_t_moments(half, 13u, &t);
    var sum = 0.0;
    for (var i = 0u; i < 6u; i++) {
        let j = 5u - i;
        let tn = t[3u + 2u * j - 1u];
        if (j % 2u == 0u) { sum += tn; } else { sum -= tn; }
    }
    return sum;
}

/// Q_0 (integrals.rs): first half C, second half T_1 − conj(C); routes near and far.
fn airlight_q_zero(half: AirlightHalf, with_re: bool) -> vec2<f32> {
    let big_h = half.big_h;
    let v_s = select(half.y_lo, 1.0 / half.y_hi, half.second);
    let v_e_infinite = half.second && half.y_lo == 0.0;
    var v_e = half.y_hi;
    if (half.second && !v_e_infinite) { v_e = 1.0 / half.y_lo; }
    let near = big_h == 0.0 || (!v_e_infinite && big_h * airlight_hypot_one(v_e) <= 1.0);
    if (near) {
        var d_im = 0.0;
        var d_re = 0.0;
        if (!v_e_infinite) {
            d_im = airlight_atan(half.dv / (1.0 + v_s * v_e));
            d_re = 0.5 * airlight_log1p(half.dv * (v_s + v_e) / (1.0 + v_s * v_s));
        } else {
            d_im = airlight_atan(1.0 / v_s);
        }
        if (big_h == 0.0) {
            if (!half.second) { return vec2<f32>(d_re, d_im); }
            var n1 = 0.0;
            if (with_re) { n1 = airlight_n1_log_part(v_s, v_e, v_e_infinite); }
            return vec2<f32>(n1, d_im);
        }
        let z_s = vec2<f32>(big_h * v_s, -big_h);
        let z_e = vec2<f32>(big_h * v_e, -big_h);
        let hdv = big_h * half.dv;
        let ein_dd = airlight_ein_divided_difference(z_s, z_e);
        let cs = airlight_cos_sin(big_h);
        let rot = vec2<f32>(cs.x, -cs.y);
        let scale = exp(big_h * v_s);
        let c = airlight_cmul(rot, vec2<f32>(d_re, d_im) - ein_dd * hdv) * scale;
        if (!half.second) { return c; }
        var n1 = 0.0;
        if (with_re) {
            let sh = airlight_cos_sin(big_h * 0.5).y;
            let ein_dd_real = airlight_ein_divided_difference(vec2<f32>(big_h * v_s, 0.0), vec2<f32>(big_h * v_e, 0.0));
            n1 = (airlight_n1_log_part(v_s, v_e, false) + (sh * sh + sh * sh) * d_re - cs.y * d_im
                - hdv * (ein_dd_real.x - airlight_cmul(rot, ein_dd).x)) * scale;
        }
        return vec2<f32>(n1, c.y);
    }
    let s_s = airlight_e1_scaled(vec2<f32>(big_h * v_s, -big_h));
    var s_e = vec2<f32>(0.0, 0.0);
    var decay = 0.0;
    // the far end contributes e^{−HΔv}·S(z_e): 0 where H·v_e overflows
    let far_finite = !v_e_infinite && airlight_is_finite(big_h * v_e);
    if (far_finite) {
        s_e = airlight_e1_scaled(vec2<f32>(big_h * v_e, -big_h));
        decay = exp(-big_h * half.dv);
    }
    let c = s_s - s_e * decay;
    if (!half.second) { return c; }
    var n1 = 0.0;
    if (with_re) {
        if (half.y_hi <= 0.25) {
            n1 = airlight_n1_series(half);
        } else {
            var e_s = airlight_zero_scratch();
            airlight_en_scaled(big_h * v_s, 1u, &e_s);
            var tail = 0.0;
            if (far_finite) {
                var e_e = airlight_zero_scratch();
                airlight_en_scaled(big_h * v_e, 1u, &e_e);
                tail = (e_e[0] - s_e.x) * decay;
            }
            n1 = (e_s[0] - s_s.x) - tail;
        }
    }
    return vec2<f32>(n1, c.y);
}

/// φ_i(x) = ∫₀¹ e^{−xt} t^i dt, i < AIRLIGHT_TERMS.
fn airlight_phi_moments(x: f32) -> array<f32, AIRLIGHT_TERMS> {
    var out = airlight_zero_terms();
    let ex = exp(-x);
    if (x <= 2.6) {
        for (var i = 0u; i < AIRLIGHT_TERMS; i++) {
            var term = 1.0 / f32(i + 1u);
            var sum = term;
            for (var j = 1u; j <= 14u; j++) {
                term *= x / f32(i + j + 1u);
                sum += term;
            }
            out[i] = ex * sum;
        }
    } else {
        var prev = (1.0 - ex) / x;
        for (var i = 0u; i < AIRLIGHT_TERMS; i++) {
            if (i > 0u) { prev = (f32(i) * prev - ex) / x; }
            out[i] = prev;
        }
    }
    return out;
}

/// out_j = Σ_i C(j,i) x_i c^{j−i}.
fn airlight_binomial_shift(x: array<f32, AIRLIGHT_TERMS>, c: f32) -> array<f32, AIRLIGHT_TERMS> {
    var out = airlight_zero_terms();
    for (var j = 0u; j < AIRLIGHT_TERMS; j++) {
        var sum = 0.0;
        var binom = 1.0;
        var cp = 1.0;
        for (var ii = 0u; ii <= j; ii++) {
            let i = j - ii;
            sum += binom * x[i] * cp;
            binom = binom * f32(i) / f32(j - i + 1u);
            cp *= c;
        }
        out[j] = sum;
    }
    return out;
}

/// The moments m_k of a half (integrals.rs), k < count (1 or AIRLIGHT_TERMS).
fn airlight_moments(half: AirlightHalf, count: u32) -> array<f32, AIRLIGHT_TERMS> {
    var m = airlight_zero_terms();
    if (!(half.dy > 0.0)) { return m; }
    let short_exp = !half.dv_infinite && half.big_h * half.dv <= 1.0;
    let short_len = half.dy <= 0.25 && (!half.second || half.dy <= half.y_lo * 0.5);
    if (short_exp && short_len) { return airlight_moments_gauss(half); }
    let yc = half.y_lo + half.dy * 0.5;
    let q0 = airlight_q_zero(half, count > 1u);
    m[0] = q0.y;
    if (count > 1u) {
        var r = airlight_zero_terms();
        if (half.second) {
            var t = airlight_zero_scratch();
            airlight_t_moments(half, AIRLIGHT_TERMS + 1u, &t);
            var x = airlight_zero_terms();
            for (var i = 0u; i < AIRLIGHT_TERMS; i++) { x[i] = t[i + 1u]; }
            r = airlight_binomial_shift(x, -yc);
        } else {
            let delta = half.dy;
            let phi = airlight_phi_moments(half.big_h * delta);
            var tau = airlight_zero_terms();
            var p = delta;
            for (var i = 0u; i < AIRLIGHT_TERMS; i++) {
                tau[i] = p * phi[i];
                p *= delta;
            }
            r = airlight_binomial_shift(tau, -delta * 0.5);
        }
        let b = vec2<f32>(yc, -1.0);
        var q = q0;
        for (var k = 1u; k < AIRLIGHT_TERMS; k++) {
            q = vec2<f32>(r[k - 1u], 0.0) - airlight_cmul(b, q);
            m[k] = q.y;
        }
    }
    return m;
}

// ---------------------------------------------------------------- combined formulation
// (kernel/src/combined.rs)

fn airlight_bounded(a: f32) -> f32 {
    return 1.0 / (a + airlight_hypot_one(a));
}

fn airlight_hypot_one(a: f32) -> f32 {
    if (abs(a) < 1.0e15) { return sqrt(1.0 + a * a); }
    return abs(a);
}

/// Σ a_k m_k on one smooth piece.
fn airlight_piece(s: AirlightScene, g: AirlightCanonical, sigma: f32, half: AirlightHalf) -> f32 {
    let m = airlight_moments(half, AIRLIGHT_TERMS);
    let a = airlight_chebyshev(s, g, sigma, half.y_lo + half.dy * 0.5, half.dy * 0.5);
    var j = 0.0;
    for (var k = 0u; k < AIRLIGHT_TERMS; k++) { j += a[k] * m[k]; }
    return j;
}

/// A piece between cone edges, cut into ⌈HΔv⌉ ≤ 8 parts when the medium is thick.
fn airlight_subdivided(s: AirlightScene, g: AirlightCanonical, sigma: f32, piece: AirlightHalf) -> f32 {
    // parts = ⌈HΔv⌉ ≤ 8 (an unbounded piece, Δv = ∞, gets 8 when H > 0)
    var parts = 1.0;
    if (piece.dy <= 0.25 && piece.big_h > 0.0) {
        if (piece.dv_infinite) { parts = 8.0; } else { parts = clamp(ceil(piece.big_h * piece.dv), 1.0, 8.0); }
    }
    if (parts <= 1.0) { return airlight_piece(s, g, sigma, piece); }
    let n = u32(parts);
    let step = piece.dy / parts;
    var total = 0.0;
    for (var i = 0u; i < 8u; i++) {
        if (i < n) {
            let lo = piece.y_lo + step * f32(i);
            var hi = lo + step;
            if (i + 1u == n) { hi = piece.y_hi; }
            let dy = hi - lo;
            var dv = dy;
            var offset = lo - piece.y_lo;
            var inf = false;
            if (piece.second) {
                if (lo == 0.0) { inf = true; dv = 0.0; } else { dv = dy / (lo * hi); }
                offset = (piece.y_hi - hi) / (hi * piece.y_hi);
            }
            let part = AirlightHalf(piece.second, piece.big_h, lo, hi, dy, dv, inf);
            total += exp(-piece.big_h * offset) * airlight_piece(s, g, sigma, part);
        }
    }
    return total;
}

/// Roots in y of c(y) = k (two at most); NaN-free: −1 marks "none".
fn airlight_crossings(sigma: f32, d_el: f32, d_c: f32, k: f32) -> vec2<f32> {
    let a = k + sigma * d_el;
    let b = -(d_c + d_c);
    let c = k - sigma * d_el;
    let disc = b * b - 4.0 * a * c;
    if (!(disc >= 0.0)) { return vec2<f32>(-1.0, -1.0); }
    var sb = 1.0;
    if (b < 0.0) { sb = -1.0; }
    let q = -0.5 * (b + sb * sqrt(disc));
    var r1 = -1.0;
    var r2 = -1.0;
    if (q != 0.0) { r1 = c / q; }
    if (a != 0.0) { r2 = q / a; }
    return vec2<f32>(r1, r2);
}

/// Σ a_k m_k on one half, split where c(y) crosses a spot cone's edges.
fn airlight_half(s: AirlightScene, g: AirlightCanonical, sigma: f32, half: AirlightHalf, isotropic: bool) -> f32 {
    if (isotropic) {
        let m = airlight_moments(half, 1u);
        return airlight_integrand(s, g, sigma, half.y_lo + half.dy * 0.5) * m[0];
    }
    var cuts = array<f32, 4>(2.0, 2.0, 2.0, 2.0);
    if (s.light_kind == AIRLIGHT_LIGHT_SPOT) {
        // a needle-thin edge is a step: one cut at its middle (both crossings coincide; the
        // zero-width piece between them is skipped below)
        var k_in = s.light_param_a;
        var k_out = s.light_param_b;
        let width = k_in - k_out;
        if (width <= AIRLIGHT_FLT_EPS) {
            k_in = k_out + width * 0.5;
            k_out = k_in;
        }
        let r_in = airlight_crossings(sigma, g.d_el, g.d_c, k_in);
        let r_out = airlight_crossings(sigma, g.d_el, g.d_c, k_out);
        cuts = array<f32, 4>(r_in.x, r_in.y, r_out.x, r_out.y);
        for (var i = 0u; i < 4u; i++) {
            if (!(cuts[i] > half.y_lo && cuts[i] < half.y_hi)) { cuts[i] = 2.0; }
        }
        // sort ascending (4 elements)
        for (var i = 0u; i < 3u; i++) {
            for (var j = 0u; j < 3u - i; j++) {
                if (cuts[j] > cuts[j + 1u]) {
                    let t = cuts[j];
                    cuts[j] = cuts[j + 1u];
                    cuts[j + 1u] = t;
                }
            }
        }
    }
    if (cuts[0] >= 2.0) {
        return airlight_piece(s, g, sigma, half);
    }
    var total = 0.0;
    var lo = half.y_lo;
    for (var i = 0u; i < 5u; i++) {
        var hi = half.y_hi;
        if (i < 4u && cuts[i] < 2.0) { hi = cuts[i]; }
        if (hi > lo) {
            let dy = hi - lo;
            var dv = dy;
            var offset = lo - half.y_lo;
            var inf = false;
            if (half.second) {
                if (lo == 0.0) { inf = true; dv = 0.0; } else { dv = dy / (lo * hi); }
                offset = (half.y_hi - hi) / (hi * half.y_hi);
            }
            let piece = AirlightHalf(half.second, half.big_h, lo, hi, dy, dv, inf);
            total += exp(-half.big_h * offset) * airlight_subdivided(s, g, sigma, piece);
            lo = hi;
        }
        if (i < 4u && cuts[i] >= 2.0) { break; }
    }
    return total;
}

/// E_2-based exact limit for a light on the ray line outside the segment (h = 0).
fn airlight_on_line(s: AirlightScene, g: AirlightCanonical) -> f32 {
    if (!g.t_hi_infinite && g.x_h > g.t_hi) {
        let f = airlight_light(s.light_kind, s.light_param_a, s.light_param_b, -g.d_el) * airlight_phase(s.phase_kind, s.phase_param_a, s.phase_param_b, s.phase_param_c, 1.0);
        let r0 = g.x_h - g.t_lo;
        let r1 = g.x_h - g.t_hi;
        return airlight_weighted(s.sigma_s, s.intensity, 2.0, s.sigma_t * r0, f * ((g.t_hi - g.t_lo) / r0 / r1));
    }
    let f = airlight_light(s.light_kind, s.light_param_a, s.light_param_b, g.d_el) * airlight_phase(s.phase_kind, s.phase_param_a, s.phase_param_b, s.phase_param_c, -1.0);
    let s0 = g.t_lo - g.x_h;
    let s1 = g.t_hi - g.x_h;
    if (s.sigma_t == 0.0) {
        var span = 1.0 / s0;
        if (!g.t_hi_infinite) { span = (s1 - s0) / s1 / s0; }
        return airlight_weighted(s.sigma_s, s.intensity, 2.0, 0.0, f * span);
    }
    let two_st = s.sigma_t + s.sigma_t;
    var e2 = airlight_zero_scratch();
    airlight_en_scaled(two_st * s0, 2u, &e2);
    // σs I e^{−x} as weighted(σs, I, 2, x), whose h = 2 cancels its 2
    let head = airlight_weighted(s.sigma_s, s.intensity, 2.0, s.sigma_t * s0, f * e2[1] / s0);
    var tail = 0.0;
    if (!g.t_hi_infinite) {
        airlight_en_scaled(two_st * s1, 2u, &e2);
        tail = airlight_weighted(s.sigma_s, s.intensity, 2.0, s.sigma_t * (s1 - s0) + s.sigma_t * s1, f * e2[1] / s1);
    }
    // head ≥ tail exactly; ∞ − ∞ (both overflowing) means the value overflows
    if (!airlight_is_finite(head)) {
        return head;
    }
    return head - tail;
}

/// H on one half: 0 where e^{−H(v − v_s)} is 1 to working precision (H·Δv < ε; unbounded:
/// H < ε²), so no H-sized intermediate can be flushed as a denormal (combined.rs `optical`).
fn airlight_optical(big_h: f32, dv: f32, infinite: bool) -> f32 {
    var negligible = big_h * dv < AIRLIGHT_FLT_EPS;
    if (infinite) { negligible = big_h < AIRLIGHT_FLT_EPS * AIRLIGHT_FLT_EPS; }
    return select(big_h, 0.0, negligible);
}

/// (2 σs I / h)·e^{−x}·j, a half's prefactor, folded exponent and sum (combined.rs
/// `weighted`): where the plain product is not finite (σs·I/h overflowing while e^{−x} or j
/// underflows) it is formed through logarithms, so a representable value stays finite.
fn airlight_weighted(sigma_s: f32, intensity: f32, h: f32, x: f32, j: f32) -> f32 {
    let plain = 2.0 * sigma_s * intensity / h * exp(-x) * j;
    if (airlight_is_finite(plain)) {
        return plain;
    }
    if (!(abs(j) > 0.0)) {
        return 0.0;
    }
    return sign(j) * exp(AIRLIGHT_LN_2 + log(sigma_s) + log(intensity) - log(h) - x + log(abs(j)));
}

/// The combined formulation on the canonical problem (combined.rs::in_scatter_canonical).
/// Returns +∞ as FLT_MAX with status INFINITE.
fn airlight_in_scatter_canonical(s: AirlightScene, g: AirlightCanonical) -> AirlightResult {
    let t0 = g.t_lo;
    let t1 = g.t_hi;
    if (!(g.t_hi_infinite || t1 > t0) || s.sigma_s * s.intensity == 0.0) {
        return AirlightResult(0.0, AIRLIGHT_STATUS_OK);
    }
    let h = g.h;
    let x_h = g.x_h;
    let inside = t0 <= x_h && (g.t_hi_infinite || x_h <= t1);
    var gap = 0.0;
    if (x_h < t0) { gap = t0 - x_h; } else if (!inside) { gap = x_h - t1; }
    if (!inside && h <= gap * AIRLIGHT_FLT_EPS * AIRLIGHT_FLT_EPS) {
        return AirlightResult(max(airlight_on_line(s, g), 0.0), AIRLIGHT_STATUS_OK);
    }
    if (h == 0.0) {
        return AirlightResult(AIRLIGHT_FLT_MAX, AIRLIGHT_STATUS_INFINITE);
    }
    let big_h = s.sigma_t * h;
    let isotropic = (s.light_kind == AIRLIGHT_LIGHT_OMNI || (s.light_kind == AIRLIGHT_LIGHT_TWO_LOBED && s.light_param_a == 0.0))
        && (s.phase_kind == AIRLIGHT_PHASE_ISOTROPIC
            || ((s.phase_kind == AIRLIGHT_PHASE_HENYEY_GREENSTEIN || s.phase_kind == AIRLIGHT_PHASE_SCHLICK) && s.phase_param_a == 0.0));
    var total = 0.0;
    if (t0 < x_h) {
        let a_s = (x_h - t0) / h;
        var t_end = x_h;
        if (!g.t_hi_infinite && t1 < x_h) { t_end = t1; }
        let a_e = (x_h - t_end) / h;
        let r_s = airlight_hypot_one(a_s);
        let r_e = airlight_hypot_one(a_e);
        let y_lo = airlight_bounded(a_s);
        let y_hi = airlight_bounded(a_e);
        let dy = (t_end - t0) / h * (1.0 + (a_s + a_e) / (r_s + r_e)) * y_lo * y_hi;
        let half = AirlightHalf(false, airlight_optical(big_h, dy, false), y_lo, y_hi, dy, dy, false);
        let j = airlight_half(s, g, -1.0, half, isotropic);
        total += airlight_weighted(s.sigma_s, s.intensity, h, big_h * r_s, j);
    }
    if (g.t_hi_infinite || t1 > x_h) {
        let t_start = max(t0, x_h);
        let a_s = (t_start - x_h) / h;
        let r_s = airlight_hypot_one(a_s);
        let y_hi = airlight_bounded(a_s);
        var y_lo = 0.0;
        var dv = 0.0;
        var dy = y_hi;
        var infinite = true;
        // An end so far out that y_lo or Δv leaves the float range is the end at t = ∞.
        let a_e = (t1 - x_h) / h;
        if (!g.t_hi_infinite && airlight_is_finite(a_e)) {
            let y_end = airlight_bounded(a_e);
            let dv_end = (t1 - t_start) / h * (1.0 + (a_s + a_e) / (r_s + airlight_hypot_one(a_e)));
            if (y_end > 0.0 && airlight_is_finite(dv_end)) {
                y_lo = y_end;
                dv = dv_end;
                dy = dv * y_lo * y_hi;
                infinite = false;
            }
        }
        let half = AirlightHalf(true, airlight_optical(big_h, dv, infinite), y_lo, y_hi, dy, dv, infinite);
        let j = airlight_half(s, g, 1.0, half, isotropic);
        total += airlight_weighted(s.sigma_s, s.intensity, h, s.sigma_t * (t_start - t0) + big_h * r_s, j);
    }
    return AirlightResult(max(total, 0.0), AIRLIGHT_STATUS_OK);
}

// ---------------------------------------------------------------- geometry and checks
// (kernel/src/geometry.rs, kernel/src/scene.rs::validate)

fn airlight_vec_finite(v: vec3<f32>) -> bool {
    return airlight_is_finite(v.x) && airlight_is_finite(v.y) && airlight_is_finite(v.z);
}

fn airlight_safe_length(v: vec3<f32>) -> f32 {
    let m = max(abs(v.x), max(abs(v.y), abs(v.z)));
    if (m == 0.0) { return 0.0; }
    return m * length(v / m);
}

/// |v| is non-zero and finite: v can be normalised (error.rs::check_vector).
fn airlight_normalisable(v: vec3<f32>) -> bool {
    let l = airlight_safe_length(v);
    return l > 0.0 && airlight_is_finite(l);
}

/// v/|v|, scaled by the largest component first (geometry.rs::normalize).
fn airlight_normalize(v: vec3<f32>) -> vec3<f32> {
    let m = max(abs(v.x), max(abs(v.y), abs(v.z)));
    let u = v / m;
    return u / length(u);
}

/// The checks of the kernel's checked API; false → the record is invalid.
fn airlight_valid(s: AirlightScene) -> bool {
    var ok = airlight_vec_finite(s.origin) && airlight_vec_finite(s.dir) && airlight_normalisable(s.dir)
        && airlight_is_finite(s.t_min) && airlight_vec_finite(s.light_position)
        && airlight_is_finite(s.intensity) && s.intensity >= 0.0
        && airlight_is_finite(s.sigma_s) && s.sigma_s >= 0.0 && airlight_is_finite(s.sigma_t) && s.sigma_t >= 0.0;
    if ((s.flags & 1u) == 0u) {
        ok = ok && airlight_is_finite(s.t_max) && s.t_min <= s.t_max;
    }
    if (s.light_kind == AIRLIGHT_LIGHT_TWO_LOBED) {
        ok = ok && airlight_vec_finite(s.light_axis) && airlight_normalisable(s.light_axis)
            && s.light_param_a >= 0.0 && s.light_param_a <= 1024.0 && fract(s.light_param_a * 0.5) == 0.0;
    } else if (s.light_kind == AIRLIGHT_LIGHT_SPOT) {
        ok = ok && airlight_vec_finite(s.light_axis) && airlight_normalisable(s.light_axis)
            && s.light_param_b < s.light_param_a && s.light_param_b >= -1.0 && s.light_param_a <= 1.0;
    } else if (s.light_kind != AIRLIGHT_LIGHT_OMNI) {
        ok = false;
    }
    let g_ok = abs(s.phase_param_a) < 1.0;
    switch s.phase_kind {
        case 0u, 1u: {}
        case 2u, 3u, 4u: { ok = ok && g_ok; }
        case 5u: { ok = ok && g_ok && abs(s.phase_param_b) < 1.0 && s.phase_param_c >= 0.0 && s.phase_param_c <= 1.0; }
        default: { ok = false; }
    }
    return ok;
}

/// World space → canonical (geometry.rs::Canonical::new).
fn airlight_canonical(s: AirlightScene) -> AirlightCanonical {
    let d = airlight_normalize(s.dir);
    var a = vec3<f32>(0.0, 0.0, 1.0);
    if (s.light_kind != AIRLIGHT_LIGHT_OMNI) { a = airlight_normalize(s.light_axis); }
    let to_light = s.light_position - s.origin;
    let x_h = dot(to_light, d);
    let perp = x_h * d - to_light;
    let h = airlight_safe_length(perp);
    var d_c = 0.0;
    if (h > 0.0) { d_c = dot(perp, a) / h; }
    let infinite = (s.flags & 1u) != 0u;
    return AirlightCanonical(h, x_h, dot(d, a), d_c, s.t_min, select(s.t_max, 0.0, infinite), infinite);
}

/// In-scattered radiance L_m of a scene (DESIGN §1): the public entry of the library.
/// Invalid scenes give (0, INVALID); a light exactly on the segment gives (FLT_MAX, INFINITE).
fn airlight_in_scatter(s: AirlightScene) -> AirlightResult {
    if (!airlight_valid(s)) {
        return AirlightResult(0.0, AIRLIGHT_STATUS_INVALID);
    }
    let r = airlight_in_scatter_canonical(s, airlight_canonical(s));
    if (!airlight_is_finite(r.in_scatter)) {
        return AirlightResult(AIRLIGHT_FLT_MAX, AIRLIGHT_STATUS_INFINITE);
    }
    return r;
}
