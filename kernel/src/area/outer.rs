//! Area lights in the other order, within a shader's loop budget (docs/DESIGN.md §12): the ray
//! outside, the directions to the emitter inside.
//!
//! `L = σs ∫ e^{−σt(t − t0)} S(x(t)) dt`, `S(x) = ∫ L_e c^{p−1} P(ω·d) e^{−σt|x − q|} dω` over the
//! directions `ω` from `x` to the emitter's points `q` (`c` the cosine at `q` between its normal
//! and `x − q`, `p` the [`Emission`](super::Emission)'s power): `dω = c dA/|x − q|²` turns the
//! element integral of [`super`] into this one, in which an evaluation is an `exp` and a phase
//! function with no loop of its own, where each of [`super`]'s point lights is a loop (more
//! than lavapipe's loop limit holds, docs/DESIGN.md §10).
//!
//! * The ray: globally adaptive Gauss–Kronrod 7/15 (`crate::extended::adaptive`) in the angle
//!   seen from the emitter's centre, `t − x_h = h' tan θ`, `h' = hypot(h, size)` (the glow is
//!   as wide as the emitter's distance or its size), split at the centre's foot, where the ray
//!   crosses a flat emitter's plane (behind it `S = 0`; in front, where the crossing lies near
//!   an edge in a narrow phase lobe, also [`CROSSING_REACH`] lobe scales of the edge's distance
//!   from it) and where it enters or leaves a sphere (inside `S = 0`); cut where the extinction
//!   from the segment's start has grown by `−ln ε` past the emitter's far side; at most
//!   [`BOUNDED_RAY_PANELS`] panels.
//! * A flat emitter: polar coordinates about `q*`, its point nearest `x`'s foot on the plane
//!   (the foot itself where it lies inside), `r = ρ₀ tan γ`, `ρ₀ = |x − q*|`, so that the
//!   `z/d³` of `dω = z dA/d³` is smooth in `γ`: a disc over the whole circle about the foot, or
//!   with `q*` on the rim over the half towards the centre (the chord `2R cos ψ`), a
//!   parallelogram as the triangles from `q*` to its edges, each in the angle `β` its far edge
//!   subtends at a distance `D` (`σ = D tan β` along it: in `ψ` a sliver's chords, from a `q*`
//!   near a corner, grow too fast); a foot inside but nearer the edge
//!   than [`EDGE_REACH`] heights is taken as one outside. Gauss–Legendre [`RADIAL`] in `γ`
//!   (graded towards the foot, `γ = s tan ϑ`, under an emission lobe as a sphere's `φ`),
//!   [`AZIMUTHAL`] in `ψ` ([`TRIANGLE_AZIMUTHAL`] in a triangle's `β`). Where a phase lobe narrower than
//!   the emitter points at it (its direction `±d` meets the plane on the emitter or within
//!   [`LOBE_REACH`] of its widths), polar about that direction instead (`flat_about_lobe`):
//!   about the foot, a Henyey–Greenstein `g = 0.99` lobe on a disc or rectangle left 1e-2 to 1e-1.
//!   A parallelogram's wedges of chords there in the angle `β` of the edge they end on, or, where
//!   the lobe's point is off the emitter, in the Mercator angle of the edge they start on.
//! * A sphere: the cap it subtends, `sin α = R/|c − x|`, about the direction of its centre, in
//!   `φ` with `sin β = sin α sin φ` (then the distance to the surface, `|c − x| cos β − R cos φ`,
//!   has no square root left at the cap's rim, and the emitted cosine is `cos φ`):
//!   Gauss–Legendre [`RADIAL`] in `φ` (graded towards the centre, `φ = s tan ϑ`, `s = 2/√(p − 1)`,
//!   where an emission lobe `c^{p−1}` is narrower than the range), [`AZIMUTHAL`] in `ψ`. Where a phase lobe narrower than
//!   the cap has its direction (`±d`) inside it or within [`LOBE_REACH`] of its widths outside,
//!   the cap about that direction instead, graded towards the lobe (`sphere_about_lobe`): about
//!   the centre, a Henyey–Greenstein `g = 0.99` lobe on the sphere left 6e-3 to 6e-2.
//!
//! The rules' sizes are the design study's (`scripts/area_ray_outer.py`); the errors over
//! tests/reference/area.jsonl are in docs/DESIGN.md §12. The shaders' `airlight_in_scatter_area`
//! (codegen/shaders/shader/airlight.wgsl) mirrors this module function by function, its rules
//! and constants taken from here at emission.

use super::{axpy, AreaScene, Emitter};
use crate::expansion::gauss_table::{GL12, GL16, GL32};
use crate::extended::{adaptive, edges_between, GAUSS_KRONROD_15};
use crate::geometry::{basis, cross, dot, length, normalize, sphere_miss, sub};
use crate::phase::PhaseFunction;
use crate::real::{exp_nonpositive, sin_cos_turns, Real};

/// The most Gauss–Kronrod 7/15 panels of [`AreaScene::in_scatter_bounded`]'s ray integral.
pub const BOUNDED_RAY_PANELS: usize = 8;

/// The relative tolerance of [`AreaScene::in_scatter_bounded`]'s ray integral (its summed
/// `|K15 − G7|`; the inner rules are fixed).
pub const BOUNDED_RAY_TOLERANCE: f64 = 1e-3;

/// Where a ray crosses a flat emitter's plane a distance `δ` from an edge in a phase lobe of
/// scale `s < 1` (`2κ`, `κ` the lobe's width), a ray panel on the emitting side ends
/// `CROSSING_REACH·δ/s` from the crossing: there the lobe's footprint `L·s` on the plane (`L` the
/// distance to the crossing) is `CROSSING_REACH` times `δ`, and `S` has passed from the edge far
/// outside the lobe to the edge through its point — a change over `δ/s`, which panels in `θ`, as
/// wide as the emitter's distance, take as a step. One such panel for the nearest edge and one
/// for the next (a crossing on an edge by a corner). `cargo run --release -p airlight-tests
/// --example area_bounded_crossing`, `g` = 0.95 and 0.99, crossings 1e-4 from an edge or corner:
/// 5.6e-4 without; the nearest edge's panel alone 3.5e-4 at 1, 1.9e-4 at 4 and 16 (the crossings
/// on an edge by a corner); both 1.8e-5 at 8, 1.1e-5 — the emitter rules' own — at 16 and 32.
/// Wider lobes are left to the θ panels' bisection, as isotropic scattering is: a `g` = 0.5 ray of
/// tests/reference/area.jsonl crossing 0.005 outside an edge was 1.3e-6 off without the panel,
/// 7.9e-5 with it (its first panels met the tolerance where, before, bisecting towards the
/// crossing had also refined the rest). docs/DESIGN.md §12.
pub const CROSSING_REACH: f64 = 16.0;

/// How far inside a flat emitter's edge, in heights `z` of `x` above its plane, its foot must be
/// for the emitter to be taken in polar coordinates about the foot (a smaller scale `s < 1` of an
/// emission lobe scales it): nearer, the chords from the foot towards the edge are short across a
/// turn of `ψ` about `π/2` from the edge, too quickly for [`AZIMUTHAL`]'s 32 points, so the edge's
/// nearest point is the centre (a disc's half-circle rule, a parallelogram's triangles). Measured
/// on the limb ray of tests/examples/area_bounded_phase.rs, a disc emitting the lobe `p = 1024`,
/// with the ray integral to 1e-8 so that the inside rules' error shows: 6.1e-4 at 0, 1.8e-5 at
/// 0.25, 2.2e-7 at 0.5, 6.0e-6 at 1, 1.4e-4 at 2.
pub const EDGE_REACH: f64 = 0.5;

/// Gauss–Legendre in a flat emitter's `γ` and a sphere's `φ` (16 points; positive half).
pub const RADIAL: [(f64, f64); 8] = GL16;

/// Gauss–Legendre in the azimuth `ψ` about a disc's `q*` or a sphere's centre (32 points;
/// positive half).
pub const AZIMUTHAL: [(f64, f64); 16] = GL32;

/// Gauss–Legendre over one of a parallelogram's triangles, in the angle `β` of its far edge
/// (12 points; positive half).
pub const TRIANGLE_AZIMUTHAL: [(f64, f64); 6] = GL12;

/// `f(x, w)` at the nodes and weights of the Gauss–Legendre rule `half` (its positive half) on
/// `[a, b]`.
#[inline]
fn each_node<T: Real>(half: &[(f64, f64)], a: T, b: T, mut f: impl FnMut(T, T)) {
    let (c, hw) = ((a + b) * T::lit(0.5), (b - a) * T::lit(0.5));
    for &(x, w) in half {
        let (x, w) = (T::lit(x) * hw, T::lit(w) * hw);
        f(c - x, w);
        f(c + x, w);
    }
}

/// `f(x, w)` at the nodes and weights of [`RADIAL`] on `[0, top]`, graded towards 0 by
/// `x = s tan ϑ` where an emission lobe's scale `s` is below `top`: `c^{p−1}` is `cos^{p−1} x`
/// about the element's normal, `1/√(p − 1)` wide, where the rule's nodes are `top/16` apart
/// (a sphere's `φ` from its cap's centre, a flat emitter's `γ` from the foot).
fn graded_radial<T: Real>(scale: Option<T>, top: T, mut f: impl FnMut(T, T)) {
    match scale.filter(|&s| s < top) {
        Some(s) => each_node(&RADIAL, T::zero(), (top / s).atan(), |node, w| {
            let (st, ct) = sin_cos_turns(node);
            f(s * st / ct, w * s / (ct * ct));
        }),
        None => each_node(&RADIAL, T::zero(), top, f),
    }
}

/// `f(sin θ, cos θ, w)` at the nodes and weights of [`RADIAL`] in `θ ∈ [from, to]`, graded from
/// `from` by `θ = from + g tan γ`, `g = max(s, from)`: a phase lobe's `P` about its direction is
/// `s` wide, and its tail at the angle `from` about as wide as `from` (`sphere_about_lobe`,
/// `flat_about_lobe`).
fn graded_from<T: Real>(scale: T, from: T, to: T, mut f: impl FnMut(T, T, T)) {
    let graded = scale.max(from);
    each_node(&RADIAL, T::zero(), ((to - from) / graded).atan(), |g, w| {
        let (sg, cg) = sin_cos_turns(g);
        let (st, ct) = sin_cos_turns(from + graded * sg / cg);
        f(st, ct, w * graded / (cg * cg));
    });
}

/// `f(direction, r, w)` at [`TRIANGLE_AZIMUTHAL`]'s nodes along the edge `a → b` seen from the
/// origin on its left (`a × b > 0`): its points `h m + σ t` (distance `h`, outward normal `m`,
/// direction `t`) taken as `σ = D tan β`, `D = hypot(h, width)`, with `w` the weight in the
/// angle `ψ` at the origin (`dψ = h dσ/(h² + σ²)`) and `r` the point's distance. In `ψ` the
/// chords of a sliver (an origin near the edge's line) grow from `h` to the edge's length within
/// `h/length` radians; in `β` they are flat over `D` ([`parallelogram`]'s triangles, `width` the
/// narrowed `ρ₀`; [`flat_about_lobe`]'s wedges, `width` the lobe's footprint `L s`; DESIGN.md §12).
fn edge_rule<T: Real>(a: (T, T), b: (T, T), width: T, f: impl FnMut((T, T), T, T)) {
    let e = (b.0 - a.0, b.1 - a.1);
    let el = e.0.hypot(e.1);
    let (h, t) = ((a.0 * b.1 - a.1 * b.0) / el, (e.0 / el, e.1 / el));
    let reach = h.hypot(width);
    line_rule(&TRIANGLE_AZIMUTHAL, h, t, reach, [a, b].map(|c| ((c.0 * t.0 + c.1 * t.1) / reach).atan()), f);
}

/// [`edge_rule`] on the line `h m + σ t` (`m = (t.1, −t.0)`) from `β = ends[0]` to `ends[1]`,
/// `σ = D tan β` (`D` = `reach`).
fn line_rule<T: Real>(rule: &[(f64, f64)], h: T, t: (T, T), reach: T, ends: [T; 2], mut f: impl FnMut((T, T), T, T)) {
    each_node(rule, ends[0], ends[1], |beta, w| {
        let (direction, r, dpsi) = line_point(h, t, reach, beta);
        f(direction, r, w * dpsi);
    });
}

/// The point `h m + σ t` of [`line_rule`]'s line at `β` (`σ = D tan β`): its direction from the
/// origin, its distance `r` and `dψ/dβ = h D/(cos²β r²)`.
fn line_point<T: Real>(h: T, t: (T, T), reach: T, beta: T) -> ((T, T), T, T) {
    let m = (t.1, -t.0);
    let (sin, cos) = sin_cos_turns(beta);
    let sigma = reach * sin / cos;
    let r2 = h * h + sigma * sigma;
    let r = r2.sqrt();
    (((h * m.0 + sigma * t.0) / r, (h * m.1 + sigma * t.1) / r), r, h * reach / (cos * cos * r2))
}

/// Where a flat emitter's wedge of chords from a phase lobe's point `q_L` off the emitter is
/// split into panels of [`TRIANGLE_AZIMUTHAL`] in the Mercator angle `u = asinh(tan δ)` of the
/// edge the chords enter by (`δ` the angle from that edge's normal through `q_L`; `dψ = sech u du`,
/// docs/DESIGN.md §12), and (the outermost) where it ends. The weight `sech u` falls as `2e^{−|u|}`,
/// so the panels widen as it falls (the lobe's edge, a step about one wide in `u`, a pole `π/2`
/// off the real axis, costs least where the weight is small): in the model of
/// `python3 scripts/mercator_panels.py`, that step anywhere in wedges up to 30 long, within
/// 6.5e-9 (one panel: 7.8e-3); beyond ±30 lies `2e^{−30} ≈ 1.9e-13` of the edge's angle.
pub const MERCATOR_CUTS: [f64; 8] = [-30.0, -14.0, -6.0, -2.0, 2.0, 6.0, 14.0, 30.0];

/// `f((cos ψ, sin ψ), w)` over the wedge of directions between `ends` (`(sin, cos)` of each)
/// whose half-lines meet the line `h n + σ t` (`n` its unit normal from the origin, `t = n`
/// turned by `+π/2`), in the Mercator angle `u = asinh(tan δ)` of the direction's angle
/// `δ = ψ − ψ_n` from `n` (`σ = h sinh u`, `dψ = sech u du`), panels at [`MERCATOR_CUTS`]. A
/// phase lobe's chords entering by the line (`flat_about_lobe` off the emitter) start at
/// `θ ≈ h cosh u / L`: flat in `ψ` but for the last `h/(L s)` before `δ = ±π/2`, where `ψ` puts no
/// node; in `u` that edge is a step about one wide at `u ≈ ln(2 L s/h)`, for every `h`.
fn mercator_rule<T: Real>(n: (T, T), ends: [(T, T); 2], mut f: impl FnMut((T, T), T)) {
    let t = (-n.1, n.0);
    let cap = T::lit(MERCATOR_CUTS[MERCATOR_CUTS.len() - 1]);
    // an end parallel to the line (or past it by rounding) at ±∞, clamped
    let [a, b] = ends.map(|(s, c)| ((s * n.0 - c * n.1) / (c * n.0 + s * n.1).max(T::zero())).asinh().max(-cap).min(cap));
    for cut in MERCATOR_CUTS.windows(2) {
        let (lo, hi) = (a.max(T::lit(cut[0])), b.min(T::lit(cut[1])));
        if lo < hi {
            each_node(&TRIANGLE_AZIMUTHAL, lo, hi, |x, w| {
                let (cosh, tanh) = (x.cosh(), x.tanh());
                f((n.0 / cosh + t.0 * tanh, n.1 / cosh + t.1 * tanh), w / cosh);
            });
        }
    }
}

/// The edges by which the half-line `r e` (`r > 0`) enters and leaves the convex polygon
/// `corners` (`None` if it misses it), each as its line's unit normal `n` from the origin and
/// distance `h`.
fn chord_edges<T: Real>(corners: &[(T, T); 4], e: (T, T)) -> Option<[((T, T), T); 2]> {
    let cross = |a: (T, T), b: (T, T)| a.0 * b.1 - a.1 * b.0;
    // (r, n, h) of the nearest and farthest crossing
    let mut entry: Option<(T, (T, T), T)> = None;
    let mut exit = entry;
    for i in 0..4 {
        let (a, b) = (corners[i], corners[(i + 1) % 4]);
        let d = (b.0 - a.0, b.1 - a.1);
        let den = cross(e, d);
        let (r, along) = (cross(a, d) / den, cross(a, e) / den);
        if r > T::zero() && along >= T::zero() && along <= T::one() {
            let len = d.0.hypot(d.1);
            let n = (d.1 / len, -d.0 / len);
            let h = n.0 * a.0 + n.1 * a.1;
            let edge = if h < T::zero() { (r, (-n.0, -n.1), -h) } else { (r, n, h) };
            if entry.map_or(true, |(nearest, _, _)| r < nearest) {
                entry = Some(edge);
            }
            if exit.map_or(true, |(farthest, _, _)| r > farthest) {
                exit = Some(edge);
            }
        }
    }
    Some([entry?, exit?].map(|(_, n, h)| (n, h)))
}

/// The azimuths of [`AZIMUTHAL`], once per ray: `(cos ψ, sin ψ, weight)` over the whole circle and
/// over the half `ψ ∈ [−π/2, π/2]`.
struct Azimuths<T> {
    circle: [(T, T, T); 32],
    half: [(T, T, T); 32],
    /// `half`'s nodes with `ψ > 0`, their weights doubled: its sum of an integrand even in `ψ`.
    even: [(T, T, T); 16],
}

impl<T: Real> Azimuths<T> {
    fn new() -> Self {
        let mut az = Azimuths { circle: [(T::zero(), T::zero(), T::zero()); 32], half: [(T::zero(), T::zero(), T::zero()); 32], even: [(T::zero(), T::zero(), T::zero()); 16] };
        let mut i = 0;
        each_node(&AZIMUTHAL, T::zero(), T::PI() + T::PI(), |psi, w| {
            let (s, c) = sin_cos_turns(psi);
            az.circle[i] = (c, s, w);
            i += 1;
        });
        i = 0;
        each_node(&AZIMUTHAL, -T::FRAC_PI_2(), T::FRAC_PI_2(), |psi, w| {
            let (s, c) = sin_cos_turns(psi);
            az.half[i] = (c, s, w);
            if psi > T::zero() {
                az.even[i / 2] = (c, s, w + w);
            }
            i += 1;
        });
        az
    }
}

/// What `S` needs of the scene besides the emitter.
struct Light<'a, T, P> {
    /// The ray's unit direction.
    d: [T; 3],
    sigma_t: T,
    radiance: T,
    /// The emission's power `p`.
    power: u32,
    /// The width scale `s = 2/√(p − 1)` of the emission's lobe `c^{p−1}` about each element's
    /// normal (none for `p = 1`).
    emission_scale: Option<T>,
    phase: &'a P,
    /// A constant phase function's value (isotropic scattering).
    constant_phase: Option<T>,
    /// The phase function's lobes ([`lobes`]).
    lobes: [Option<(T, T)>; 2],
    azimuths: Azimuths<T>,
}

/// The phase function's lobes at `μ = ±1` as `(±1, s)`: a singularity at the real cosine `μ*`
/// beyond `±1` ([`PhaseFunction::singularities`]) makes a lobe about `±d` as wide as
/// `κ = √(2(|μ*| − 1))` (Henyey–Greenstein `(1 − |g|)/√|g|`), and `s = 2κ` is the scale of the
/// radial map about it (`scripts/area_lobe_study.py`: `κ` and `2κ` measured, `2κ` 3 times the
/// more accurate on a sphere looked at through `g = 0.95` and 0.99).
fn lobes<T: Real, P: PhaseFunction<T>>(phase: &P) -> [Option<(T, T)>; 2] {
    let cosines = phase.singularities().map_or([T::infinity(); 2], |s| s.cosines);
    cosines.map(|mu| {
        let gap = mu.abs() - T::one();
        (mu.is_finite() && gap > T::zero()).then(|| (T::one().copysign(mu), T::lit(2.0) * (gap + gap).sqrt()))
    })
}

impl<T: Real, P: PhaseFunction<T>> Light<'_, T, P> {
    /// Whether a flat emitter is taken about the foot `depth` inside its edge at the height `z`
    /// (else about the edge's nearest point): `depth ≥ EDGE_REACH·z·min(1, s)`, `s` the emission
    /// lobe's scale.
    fn far_from_edge(&self, depth: T, z: T) -> bool {
        depth >= T::lit(EDGE_REACH) * self.narrowed(z)
    }

    /// `length·min(1, s)`, `s` the emission lobe's scale: how far from a flat emitter's point
    /// nearest `x` its elements still shine at `x` (a length at `x`'s distance `length`).
    fn narrowed(&self, length: T) -> T {
        length * self.emission_scale.map_or(T::one(), |s| s.min(T::one()))
    }

    /// `P(μ)`.
    #[inline]
    fn phase(&self, mu: T) -> T {
        self.constant_phase.unwrap_or_else(|| self.phase.eval(mu))
    }

    /// `P(sign·cos θ)` at the angle `θ` from a lobe's direction `sign·d`, given `sin θ` and
    /// `cos θ`, with `1 ∓ cos θ` to their relative precision as `sin²θ/(1 ± cos θ)`
    /// ([`PhaseFunction::eval_sides`]): formed from the rounded cosine, `1 − cos θ` loses
    /// `ε/(1 − cos θ)` of itself, which a lobe's peak amplifies.
    #[inline]
    fn phase_about(&self, sign: T, (st, ct): (T, T)) -> T {
        self.constant_phase.unwrap_or_else(|| {
            let (near, far) = if ct >= T::zero() { (st * st / (T::one() + ct), T::one() + ct) } else { (T::one() - ct, st * st / (T::one() - ct)) };
            let (om, op) = if sign > T::zero() { (near, far) } else { (far, near) };
            self.phase.eval_sides(sign * ct, om, op)
        })
    }

    /// `L_e c^{p−1}`.
    #[inline]
    fn emitted(&self, c: T) -> T {
        if self.power == 1 {
            self.radiance
        } else {
            self.radiance * c.powi(self.power as i32 - 1)
        }
    }
}

/// A point `x` above a flat emitter's plane: its height `z > 0`, the plane's unit vectors'
/// dot products with the ray's direction (`a1`, `a2`, `n` in [`Frame`]'s order), `q* − foot` in
/// the plane's coordinates, and `ρ₀ = |x − q*|`.
struct Above<T> {
    z: T,
    dirs: [T; 3],
    off: (T, T),
    rho0: T,
}

impl<T: Real> Above<T> {
    fn new(z: T, dirs: [T; 3], off: (T, T)) -> Self {
        Above { z, dirs, off, rho0: (z * z + off.0 * off.0 + off.1 * off.1).sqrt() }
    }
}

/// A flat emitter's unit normal `n` and the plane's unit vectors `a1`, `a2`.
type Frame<T> = ([T; 3], [T; 3], [T; 3]);

/// `∫ L_e c^{p−1} P e^{−σt d} z/d³ r dr` along the direction `e` from `q*` out to `r_max`, in
/// `γ` (`r = ρ₀ tan γ`).
fn radial<T: Real, P: PhaseFunction<T>>(light: &Light<'_, T, P>, above: &Above<T>, e: (T, T), r_max: T) -> T {
    let Above { z, dirs: [a1d, a2d, nd], off, rho0 } = *above;
    let mut sum = T::zero();
    graded_radial(light.emission_scale, (r_max / rho0).atan(), |g, w| {
        let (s, c) = sin_cos_turns(g);
        let r = rho0 * s / c;
        let dr = rho0 / (c * c);
        let (px, py) = (off.0 + r * e.0, off.1 + r * e.1);
        let dist = (z * z + px * px + py * py).sqrt();
        let inv = dist.recip();
        let cos = z * inv;
        let phase = light.phase((px * a1d + py * a2d - z * nd) * inv);
        sum = sum + w * light.emitted(cos) * exp_nonpositive(-light.sigma_t * dist) * phase * cos * inv * inv * r * dr;
    });
    sum
}

/// `S(x)` of a disc (centre `c`, unit normal `n`, the plane's unit vectors `a1`, `a2`, radius `R`).
fn disc<T: Real, P: PhaseFunction<T>>(light: &Light<'_, T, P>, x: [T; 3], c: [T; 3], (n, a1, a2): Frame<T>, radius: T) -> T {
    let rel = sub(x, c);
    let z = dot(rel, n);
    if !(z > T::zero()) {
        return T::zero();
    }
    let (fx, fy) = (dot(rel, a1), dot(rel, a2));
    let rf = (fx * fx + fy * fy).sqrt();
    let dirs = [dot(a1, light.d), dot(a2, light.d), dot(n, light.d)];
    let outline = Outline::Circle { c: (-fx, -fy), radius };
    if let Some(lobe) = flat_lobe(light, z, dirs, &outline, ((-fx, -fy), radius)) {
        return flat_about_lobe(light, z, &outline, &lobe);
    }
    let mut sum = T::zero();
    if rf <= radius && (rf == T::zero() || light.far_from_edge(radius - rf, z)) {
        // about the foot: the chord to the rim along e, the positive root of r² + 2br + k = 0
        let above = Above::new(z, dirs, (T::zero(), T::zero()));
        let k = (rf - radius) * (rf + radius);
        for &(cos, sin, w) in &light.azimuths.circle {
            let b = fx * cos + fy * sin;
            let root = (b * b - k).sqrt();
            let r_max = if b > T::zero() { -k / (b + root) } else { root - b };
            sum = sum + w * radial(light, &above, (cos, sin), r_max);
        }
    } else {
        // about the rim's point nearest the foot, over the half towards the centre (u); a foot
        // inside by δ = radius − rf has gap −δ
        let (ux, uy) = (-fx / rf, -fy / rf);
        let gap = rf - radius;
        let above = Above::new(z, dirs, (gap * ux, gap * uy));
        for &(cos, sin, w) in &light.azimuths.half {
            let e = (cos * ux - sin * uy, cos * uy + sin * ux);
            sum = sum + w * radial(light, &above, e, (radius + radius) * cos);
        }
    }
    sum
}

/// `S(x)` of the parallelogram `p0 + u·eu + v·ev` (unit normal `n` along `eu × ev`, `a1 = eu/|eu|`,
/// `a2 = n × a1`).
fn parallelogram<T: Real, P: PhaseFunction<T>>(light: &Light<'_, T, P>, x: [T; 3], p0: [T; 3], (eu, ev): ([T; 3], [T; 3]), (n, a1, a2): Frame<T>) -> T {
    let rel = sub(x, p0);
    let z = dot(rel, n);
    if !(z > T::zero()) {
        return T::zero();
    }
    let (corners, foot) = parallelogram_corners(rel, (eu, ev), (n, a1, a2));
    let (u2, v2) = (corners[1], corners[3]);
    let det = u2.0 * v2.1 - u2.1 * v2.0;
    let dirs = [dot(a1, light.d), dot(a2, light.d), dot(n, light.d)];
    let about_foot = Outline::polygon_about(corners, foot);
    let half = T::lit(0.5);
    let size = half * ((u2.0 + v2.0).hypot(u2.1 + v2.1)).max((u2.0 - v2.0).hypot(u2.1 - v2.1));
    let centre = (half * corners[2].0 - foot.0, half * corners[2].1 - foot.1);
    if let Some(lobe) = flat_lobe(light, z, dirs, &about_foot, (centre, size)) {
        return flat_about_lobe(light, z, &about_foot, &lobe);
    }
    let (edge, inside) = about_foot.boundary((T::zero(), T::zero()));
    let q = if inside && light.far_from_edge(edge.0.hypot(edge.1), z) { foot } else { (edge.0 + foot.0, edge.1 + foot.1) };
    let above = Above::new(z, dirs, (q.0 - foot.0, q.1 - foot.1));
    // a triangle (q*, C_i, C_{i+1}) without area (q* on its edge) is left out
    let thin = T::epsilon() * det.abs();
    let width = light.narrowed(above.rho0);
    let mut sum = T::zero();
    for i in 0..4 {
        let (a, b) = (corners[i], corners[(i + 1) % 4]);
        let (a, b) = ((a.0 - q.0, a.1 - q.1), (b.0 - q.0, b.1 - q.1));
        if a.0 * b.1 - a.1 * b.0 > thin {
            edge_rule(a, b, width, |dir, r, w| sum = sum + w * radial(light, &above, dir, r));
        }
    }
    sum
}

/// The parallelogram `p0 + u·eu + v·ev`'s corners in its plane's coordinates, counter-clockwise
/// about `n`, and the foot of `x` (`rel = x − p0`).
fn parallelogram_corners<T: Real>(rel: [T; 3], (eu, ev): ([T; 3], [T; 3]), (_, a1, a2): Frame<T>) -> ([(T, T); 4], (T, T)) {
    let (u2, v2) = ((dot(eu, a1), dot(eu, a2)), (dot(ev, a1), dot(ev, a2)));
    ([(T::zero(), T::zero()), u2, (u2.0 + v2.0, u2.1 + v2.1), v2], (dot(rel, a1), dot(rel, a2)))
}

/// The point of the edge `a → b` nearest `q`.
fn edge_nearest<T: Real>(a: (T, T), b: (T, T), q: (T, T)) -> (T, T) {
    let e = (b.0 - a.0, b.1 - a.1);
    let s = (((q.0 - a.0) * e.0 + (q.1 - a.1) * e.1) / (e.0 * e.0 + e.1 * e.1)).max(T::zero()).min(T::one());
    (a.0 + s * e.0, a.1 + s * e.1)
}

/// A flat emitter's outline in its plane's coordinates (along `a1`, `a2` of [`Frame`]) about
/// `x`'s foot.
enum Outline<T> {
    Circle { c: (T, T), radius: T },
    /// A parallelogram's corners, counter-clockwise about the normal.
    Polygon([(T, T); 4]),
}

impl<T: Real> Outline<T> {
    /// A parallelogram's outline about `foot` from its corners ([`parallelogram_corners`]).
    fn polygon_about(corners: [(T, T); 4], foot: (T, T)) -> Self {
        Outline::Polygon(corners.map(|c| (c.0 - foot.0, c.1 - foot.1)))
    }

    /// The interval `[r_a, r_b]` of `r ≥ 0` for which `q + r e` lies on the emitter (`None` if
    /// the half-line misses it).
    fn chord(&self, q: (T, T), e: (T, T)) -> Option<(T, T)> {
        match *self {
            Outline::Circle { c, radius } => {
                // r² a + 2 r b + k = 0
                let (qx, qy) = (q.0 - c.0, q.1 - c.1);
                let (a, b) = (e.0 * e.0 + e.1 * e.1, qx * e.0 + qy * e.1);
                let dq = qx.hypot(qy);
                let k = (dq - radius) * (dq + radius);
                let disc = b * b - a * k;
                if !(disc > T::zero()) {
                    return None;
                }
                let s = -b - disc.sqrt().copysign(b);
                let (r1, r2) = (s / a, k / s);
                let (lo, hi) = (r1.min(r2), r1.max(r2));
                (hi > T::zero()).then(|| (lo.max(T::zero()), hi))
            }
            Outline::Polygon(corners) => {
                // clipped by each edge's half-plane (Cyrus–Beck)
                let (mut lo, mut hi) = (T::zero(), T::infinity());
                for i in 0..4 {
                    let (a, b) = (corners[i], corners[(i + 1) % 4]);
                    let m = (b.1 - a.1, a.0 - b.0);
                    let (num, den) = ((q.0 - a.0) * m.0 + (q.1 - a.1) * m.1, e.0 * m.0 + e.1 * m.1);
                    if den > T::zero() {
                        hi = hi.min(-num / den);
                    } else if den < T::zero() {
                        lo = lo.max(-num / den);
                    } else if num > T::zero() {
                        return None;
                    }
                }
                (lo < hi).then_some((lo, hi))
            }
        }
    }

    /// The emitter's point nearest `q` (`q` itself on the emitter).
    fn nearest(&self, q: (T, T)) -> (T, T) {
        match self.boundary(q) {
            (_, true) => q,
            (edge, false) => edge,
        }
    }

    /// The point of the emitter's edge nearest `q`, and whether `q` is on the emitter.
    fn boundary(&self, q: (T, T)) -> ((T, T), bool) {
        match *self {
            Outline::Circle { c, radius } => {
                let (qx, qy) = (q.0 - c.0, q.1 - c.1);
                let dq = qx.hypot(qy);
                ((c.0 + qx * radius / dq, c.1 + qy * radius / dq), dq <= radius)
            }
            Outline::Polygon(corners) => {
                let mut best = (T::infinity(), q);
                let mut inside = true;
                for i in 0..4 {
                    let (a, b) = (corners[i], corners[(i + 1) % 4]);
                    inside = inside && (q.0 - a.0) * (b.1 - a.1) - (q.1 - a.1) * (b.0 - a.0) <= T::zero();
                    let p = edge_nearest(a, b, q);
                    let dd = (p.0 - q.0) * (p.0 - q.0) + (p.1 - q.1) * (p.1 - q.1);
                    if dd < best.0 {
                        best = (dd, p);
                    }
                }
                (best.1, inside)
            }
        }
    }

    /// The distances of the foot (the origin) from the outline's nearest edge and from the next
    /// (a circle has one edge, the next at ∞).
    fn distances(&self) -> [T; 2] {
        match *self {
            Outline::Circle { c, radius } => [(c.0.hypot(c.1) - radius).abs(), T::infinity()],
            Outline::Polygon(corners) => {
                let mut nearest = [T::infinity(); 2];
                for i in 0..4 {
                    let p = edge_nearest(corners[i], corners[(i + 1) % 4], (T::zero(), T::zero()));
                    let distance = p.0.hypot(p.1);
                    if distance < nearest[0] {
                        nearest = [distance, nearest[0]];
                    } else if distance < nearest[1] {
                        nearest[1] = distance;
                    }
                }
                nearest
            }
        }
    }
}

/// A phase lobe pointing at a flat emitter: its direction `p = sign·d` in the plane's coordinates
/// (`p·n < 0`, towards the plane), its radial scale `s` ([`lobes`]), `x`'s distance `L` from the
/// point `q_L` where `p` meets the plane, `q_L` (about the foot), and whether it is on the emitter.
struct FlatLobe<T> {
    p: [T; 3],
    sign: T,
    scale: T,
    l: T,
    q: (T, T),
    on_emitter: bool,
}

/// The phase lobe to take a flat emitter about, as a sphere's (`sphere_about_lobe`): one narrower
/// than the emitter seen from `x` (`s` below twice `atan(size/|centre − x|)`) whose direction meets
/// the plane on the emitter or within [`LOBE_REACH`] scales of it (`x = (0, 0, z)` above the
/// foot; `dirs` the ray's direction in the plane's coordinates).
fn flat_lobe<T: Real, P: PhaseFunction<T>>(light: &Light<'_, T, P>, z: T, dirs: [T; 3], outline: &Outline<T>, (centre, size): ((T, T), T)) -> Option<FlatLobe<T>> {
    let reach = (size / centre.0.hypot(centre.1).hypot(z)).atan();
    light.lobes.iter().flatten().find_map(|&(sign, scale)| {
        let p = dirs.map(|c| sign * c);
        if !(p[2] < T::zero()) || !(scale < reach + reach) {
            return None;
        }
        let l = z / -p[2];
        let q = (l * p[0], l * p[1]);
        let near = outline.nearest(q);
        let to_near = [near.0, near.1, -z];
        let cos = (dot(p, to_near) / length(to_near)).min(T::one());
        // on it, or outside by no more than the rounding of q_L and the corners about the foot
        let on_emitter = (near.0 - q.0).hypot(near.1 - q.1) <= T::lit(16.0) * T::epsilon() * (q.0.hypot(q.1) + size + z);
        (on_emitter || cos.acos() < T::lit(LOBE_REACH) * scale).then_some(FlatLobe { p, sign, scale, l, q, on_emitter })
    })
}

/// `S(x)` of a flat emitter about a phase lobe's direction `p` ([`flat_lobe`]): polar about `p`,
/// `ω = cos θ p + sin θ w_ψ`, `w_ψ = cos ψ u + sin ψ v`. The half-plane of `ψ` meets the
/// emitter's plane in the half-line `q_L + r (w_ψ + k p)`, `k = −(w_ψ·n)/(p·n)`, on which
/// `tan θ = r/(L + k r)`; there the distance is `z/c` and the emitted cosine
/// `c = −(p·n)(cos θ − k sin θ)`. Each `θ` range (the emitter's chord of that half-line), graded
/// from its start by `θ = θ_a + max(s, θ_a) tan γ`, by [`RADIAL`]. A disc holding `q_L`: the half
/// of the directions towards the rim's nearest point in the angle `β` of the rim's tangent there
/// ([`line_rule`] by [`RADIAL`]; `D = hypot(h, min(L s, the rim's half chord along the tangent
/// through q_L))`, the chords' longest), the far half in `ψ` ([`AZIMUTHAL`]); off it, over the
/// wedge of the disc's tangents from `q_L` (`ψ = ψ_m + Ψ sin φ`, the chords close like a square
/// root there). A parallelogram holding
/// `q_L` ([`flat_lobe`]: also where rounding puts it just outside) is taken edge by edge, each
/// wedge of chords ending on an edge in the angle `β` that edge subtends ([`edge_rule`], as
/// [`parallelogram`]'s triangles); off it, over the wedges between its corners seen from `q_L`
/// (each chord's ends on one edge each), each in the Mercator angle of the edge its chords
/// enter by ([`mercator_rule`]), but where the edge they leave by is nearer than `L s`, the half
/// of the wedge more nearly parallel to it in its angle `β` ([`line_rule`]); docs/DESIGN.md §12.
fn flat_about_lobe<T: Real, P: PhaseFunction<T>>(light: &Light<'_, T, P>, z: T, outline: &Outline<T>, lobe: &FlatLobe<T>) -> T {
    let FlatLobe { p, sign, scale, l, q, on_emitter } = *lobe;
    let (u, v) = basis(p);
    let pn = -p[2];
    // a direction in the plane as the azimuth ψ of the half-plane it lies in
    let azimuth = |e: (T, T)| (e.0 * v[0] + e.1 * v[1]).atan2(e.0 * u[0] + e.1 * u[1]);
    // the half-plane of (cos ψ, sin ψ): k and the direction w_ψ + k p of its half-line
    let half_line = |cos: T, sin: T| {
        let w = [cos * u[0] + sin * v[0], cos * u[1] + sin * v[1], cos * u[2] + sin * v[2]];
        let k = w[2] / pn;
        (k, (w[0] + k * p[0], w[1] + k * p[1]))
    };
    let along = |cos: T, sin: T| {
        let (k, e) = half_line(cos, sin);
        let Some((ra, rb)) = outline.chord(q, e) else {
            return T::zero();
        };
        let mut sum = T::zero();
        graded_from(scale, ra.atan2(l + k * ra), rb.atan2(l + k * rb), |st, ct, w| {
            let c = pn * (ct - k * st);
            if c > T::zero() {
                sum = sum + w * light.emitted(c) * exp_nonpositive(-light.sigma_t * z / c) * light.phase_about(sign, (st, ct)) * st;
            }
        });
        sum
    };
    let wrap = |a: T| a - (T::PI() + T::PI()) * (a / (T::PI() + T::PI())).round();
    // a point e of the plane (about q_L) in the lobe's plane: its angle is the azimuth ψ of its
    // half-plane, its length about L θ
    let lobe_plane = |e: (T, T)| (e.0 * u[0] + e.1 * u[1], e.0 * v[0] + e.1 * v[1]);
    let mut sum = T::zero();
    match *outline {
        Outline::Circle { c, radius } => {
            if on_emitter {
                // the half of the directions towards the rim's nearest point in the angle β of
                // its tangent there (in the lobe's plane the line h n + σ t, as a
                // parallelogram's edge: σ = D tan β, D = hypot(h, min(L s, half chord))), the
                // far half in ψ
                let (dx, dy) = (q.0 - c.0, q.1 - c.1);
                let d = dx.hypot(dy);
                let m = if d > T::zero() { (dx / d, dy / d) } else { (T::one(), T::zero()) };
                let (rim, along_rim) = (lobe_plane((c.0 + radius * m.0 - q.0, c.1 + radius * m.1 - q.1)), lobe_plane((-m.1, m.0)));
                let tl = along_rim.0.hypot(along_rim.1);
                // t turned by −π/2 the tangent's normal out of the disc, h q_L's distance inside
                // it (≤ 0 for a q_L on the rim or outside by rounding, [`flat_lobe`])
                let mut t = (along_rim.0 / tl, along_rim.1 / tl);
                let outward = lobe_plane(m);
                if t.1 * outward.0 - t.0 * outward.1 < T::zero() {
                    t = (-t.0, -t.1);
                }
                let h = t.1 * rim.0 - t.0 * rim.1;
                // the chord of the rim parallel to the tangent through q_L: its half
                let half_chord = tl * ((radius - d) * (radius + d)).max(T::zero()).sqrt();
                // (none with q_L on the rim: those chords have no length)
                if h > T::zero() {
                    line_rule(&RADIAL, h, t, h.hypot((l * scale).min(half_chord)), [-T::FRAC_PI_2(), T::FRAC_PI_2()], |dir, _, w| sum = sum + w * along(dir.0, dir.1));
                }
                let n = (t.1, -t.0);
                for &(cos, sin, w) in &light.azimuths.half {
                    sum = sum + w * along(-(n.0 * cos + t.0 * sin), -(n.1 * cos + t.1 * sin));
                }
            } else {
                // the tangents from q_L, at ±β from the centre's direction
                let (dx, dy) = (c.0 - q.0, c.1 - q.1);
                let dq = dx.hypot(dy);
                let (sb, cb) = (radius / dq, ((dq - radius) * (dq + radius)).sqrt() / dq);
                let mid = azimuth((dx, dy));
                let ends = [(dx * cb - dy * sb, dy * cb + dx * sb), (dx * cb + dy * sb, dy * cb - dx * sb)].map(|e| wrap(azimuth(e) - mid));
                let (centre, half) = (mid + (ends[0] + ends[1]) * T::lit(0.5), (ends[0] - ends[1]).abs() * T::lit(0.5));
                for &(cos, sin, w) in &light.azimuths.half {
                    let (s, c) = sin_cos_turns(centre + half * sin);
                    sum = sum + w * half * cos * along(c, s);
                }
            }
        }
        Outline::Polygon(corners) if on_emitter => {
            // the chords of the wedge between two corners end on the edge between them, in the
            // lobe's plane the segment between the corners' images; they turn as a
            // parallelogram's triangles do, with the lobe's footprint L s in place of ρ₀ min(1, s)
            let images = corners.map(|c| lobe_plane((c.0 - q.0, c.1 - q.1)));
            // the image keeps or reverses the corners' turn; an edge q_L is on (or outside by
            // rounding, [`flat_lobe`]) has no chords of its own
            let cross = |i: usize| images[i].0 * images[(i + 1) % 4].1 - images[i].1 * images[(i + 1) % 4].0;
            let turn = (0..4).fold(T::zero(), |sum, i| sum + cross(i));
            for i in 0..4 {
                let (a, b) = (images[i], images[(i + 1) % 4]);
                if cross(i) * turn > T::zero() {
                    let (a, b) = if turn < T::zero() { (b, a) } else { (a, b) };
                    edge_rule(a, b, l * scale, |dir, _, w| sum = sum + w * along(dir.0, dir.1));
                }
            }
        }
        Outline::Polygon(corners) => {
            // the wedges between the corners' azimuths about the centre's, in order, each in the
            // Mercator angle of the edge its chords enter by
            let images = corners.map(|c| lobe_plane((c.0 - q.0, c.1 - q.1)));
            let mid = azimuth((T::lit(0.5) * (corners[0].0 + corners[2].0) - q.0, T::lit(0.5) * (corners[0].1 + corners[2].1) - q.1));
            let mut psi = corners.map(|c| wrap(azimuth((c.0 - q.0, c.1 - q.1)) - mid));
            psi.sort_unstable_by(|a, b| a.partial_cmp(b).unwrap_or(core::cmp::Ordering::Equal));
            for i in 0..3 {
                let (from, to) = (mid + psi[i], mid + psi[i + 1]);
                let half = T::lit(0.5) * (from + to);
                let (sm, cm) = sin_cos_turns(half);
                let Some([(entry, _), (exit, h)]) = chord_edges(&images, (cm, sm)) else {
                    each_node(&TRIANGLE_AZIMUTHAL, from, to, |a, w| {
                        let (s, c) = sin_cos_turns(a);
                        sum = sum + w * along(c, s);
                    });
                    continue;
                };
                // the chords' ends on an exit edge nearer than the lobe's footprint grow as a
                // triangle's towards the end more nearly parallel to it: that half in the angle β
                // of the exit edge ([`line_rule`], D = hypot(h, L s)), the rest in the Mercator
                // angle of the entry edge
                let mut mercator = [from, to].map(|a| sin_cos_turns(a));
                if h > T::zero() && h < l * scale {
                    let (t, reach) = ((-exit.1, exit.0), h.hypot(l * scale));
                    let cos_exit = |(s, c): (T, T)| c * exit.0 + s * exit.1;
                    let beta = |(s, c): (T, T)| ((c * t.0 + s * t.1) * h / (cos_exit((s, c)).max(T::zero()) * reach)).atan();
                    // the end more nearly parallel to the exit edge to the mid direction; the
                    // Mercator range from there
                    let parallel = if cos_exit(mercator[0]) < cos_exit(mercator[1]) { 0 } else { 1 };
                    let mut exit_half = [(sm, cm); 2];
                    exit_half[parallel] = mercator[parallel];
                    mercator[parallel] = (sm, cm);
                    line_rule(&TRIANGLE_AZIMUTHAL, h, t, reach, exit_half.map(beta), |dir, _, w| sum = sum + w * along(dir.0, dir.1));
                }
                mercator_rule(entry, mercator, |(c, s), w| sum = sum + w * along(c, s));
            }
        }
    }
    sum
}

/// The cap a sphere of radius `R` subtends from `x`: the unit direction `a` of its centre at
/// distance `dc`, and `cos α = √(1 − (R/dc)²)`.
struct Cap<T> {
    a: [T; 3],
    dc: T,
    radius: T,
    cos_a: T,
    /// The cap's angular radius `α = asin(R/dc)`.
    alpha: T,
}

/// `S(x)` of a sphere of radius `R` whose centre lies at `v = c − x`, `gap = |v| − R` apart
/// ([`SphereFoot::at`]); `0` inside it.
fn sphere<T: Real, P: PhaseFunction<T>>(light: &Light<'_, T, P>, v: [T; 3], radius: T, gap: T) -> T {
    // inside, or beyond the float range (a cap of no size)
    if !(gap > T::zero() && gap.is_finite()) {
        return T::zero();
    }
    let length = length(v);
    let a = [v[0] / length, v[1] / length, v[2] / length];
    // sin α = R/dc, cos α = √((dc − R)(dc + R))/dc from the gap itself: near the limb `dc`
    // rounded holds `dc − R` only to ε·dc
    let dc = radius + gap;
    let sin_a = radius / dc;
    let cos_a = ((gap / dc) * (T::one() + sin_a)).sqrt();
    let alpha = sin_a.atan2(cos_a);
    let cap = Cap { a, dc, radius, cos_a, alpha };
    // a lobe whose direction falls inside the cap or near it: polar about it instead
    for &(sign, scale) in light.lobes.iter().flatten() {
        let p = [sign * light.d[0], sign * light.d[1], sign * light.d[2]];
        let cos_p = dot(a, p);
        // a lobe narrower than the cap (κ < α), inside it or outside within LOBE_REACH scales of
        // its rim or the cap's own radius α (there P falls by more than 3³ across the cap, which
        // the cap rule's nodes do not follow), beyond the great circle opposite the centre
        // (beside the sphere) only one narrower than BESIDE_SCALE
        let beside = cos_p < -cap.cos_a;
        if scale < alpha + alpha && (!beside || scale < T::lit(BESIDE_SCALE)) && (cos_p > cap.cos_a || cos_p.acos() - alpha < (T::lit(LOBE_REACH) * scale).max(alpha)) {
            return sphere_about_lobe(light, &cap, (p, sign, cos_p), scale);
        }
    }
    let (e1, e2) = basis(a);
    let (ad, e1d, e2d) = (dot(a, light.d), dot(e1, light.d), dot(e2, light.d));
    // a constant phase function's integral round the circle, 2π·P
    let isotropic = light.constant_phase.map(|p| (T::PI() + T::PI()) * p);
    let mut sum = T::zero();
    graded_radial(light.emission_scale, T::FRAC_PI_2(), |phi, w| {
        let (sp, cp) = sin_cos_turns(phi);
        let sb = sin_a * sp;
        let cb = ((T::one() - sb) * (T::one() + sb)).sqrt();
        let dist = (dc * cb - radius * cp).max(T::zero());
        let around = isotropic.unwrap_or_else(|| {
            let mut around = T::zero();
            for &(cos, sin, wpsi) in &light.azimuths.circle {
                around = around + wpsi * light.phase.eval(cb * ad + sb * (cos * e1d + sin * e2d));
            }
            around
        });
        sum = sum + w * light.emitted(cp) * sin_a * sin_a * sp * cp / cb * exp_nonpositive(-light.sigma_t * dist) * around;
    });
    sum
}

/// How far outside a sphere's cap or a flat emitter, in radial scales `s` of a phase lobe, the
/// lobe's direction may lie for the emitter to be taken about it (`sphere_about_lobe`,
/// `flat_about_lobe`): 8 scales (16 widths) from its
/// direction a Henyey–Greenstein lobe has fallen to `257^{−3/2}` = 2.4e-4 of its peak, smooth on
/// the cap rule's nodes (tests/examples/area_bounded_phase.rs: its rays past the limb were 4.1e-4
/// to 6.0e-2 off with the cap rule, 3.9e-6 to 1.7e-5 with this).
pub const LOBE_REACH: f64 = 8.0;

/// How far past its start, in radians, a sphere's `θ` range about a phase lobe is cut in two
/// where it is longer than [`LOBE_REACH`] of its grading scales (`sphere_about_lobe`): beyond
/// the cut the lobe's tail is graded from there by its own distance. In one rule `θ = s tan γ`
/// puts the last `π/2` of a range reaching to `θ ≈ π` within `s` of `γ = π/2`, where the
/// tail's fall by `sin θ` and the cap's far rim are not followed: a ray leaving a sphere's limb
/// behind it was 7.7e-4 to 1.0e-3 off in `g = 0.99` fog, 1.8e-4 to 2.2e-4 at `0.95`, point by
/// point (short segments against the nested construction), cut here within 2.2e-6; the part
/// behind the sphere in `cargo run --release -p airlight-tests --example area_bounded_limb`
/// 6.0e-4 → 1.2e-4 (the ray's own rule at its tolerance; DESIGN.md §12).
pub const LOBE_TAIL: f64 = 0.25;

/// The widest phase lobe (radial scale `s`, [`LOBE_REACH`]'s) a sphere is taken about from beside
/// it, where the lobe's opposite direction lies in the cap as well (`sphere_about_lobe`, 64
/// directions against the cap rule's 32): `cargo run --release -p airlight-tests --example
/// area_bounded_limb`, the part of a grazing ray behind the sphere, `g` = 0.9 (`s` = 0.21) 7.3e-4
/// to 1.1e-3 off about the centre, 1.9e-5 to 5.1e-5 about the lobe; area.jsonl's `inside` sphere
/// at `g` = 0.8 (`s` = 0.45) within 4.8e-5 about the centre, at 14 times the cost about the lobe.
pub const BESIDE_SCALE: f64 = 0.25;

/// `S(x)` of a sphere whose [`Cap`] holds (or nearly) the direction `p = sign·d` of a phase lobe
/// of radial scale `s` ([`lobes`]; `cos_p = a·p`): polar about `p`,
/// `ω = cos θ p + sin θ (cos ψ u + sin ψ v)`, `θ = s tan γ` from 0 to the cap's rim in each `ψ`
/// (`cos θ (a·p) + sin θ (a·e_ψ) = cos α`), Gauss–Legendre [`RADIAL`] in `γ` (a long range in two,
/// [`LOBE_TAIL`]); in `ψ`, with `p`
/// inside the cap, the half towards the rim's nearest point in the angle `β` of the rim's
/// tangent there ([`RADIAL`]) and the far half [`AZIMUTHAL`] (a disc holding the lobe's point,
/// [`flat_about_lobe`]: over the whole circle in `ψ` a ray entering the sphere 1e-5 of its radius
/// inside its limb was 8.7e-3 off in `g = 0.95` fog), outside [`AZIMUTHAL`] over the wedge that
/// meets the cap, or, beside the sphere (`−p` in the cap too, [`BESIDE_SCALE`]), the half towards
/// the rim in its tangent's Mercator angle ([`mercator_rule`]) and the far half in `ψ`; the
/// distance to the surface `dc (ω·a) − √(R² − dc²(1 − (ω·a)²))`, the emitted cosine that root
/// over `R`.
fn sphere_about_lobe<T: Real, P: PhaseFunction<T>>(light: &Light<'_, T, P>, cap: &Cap<T>, (p, sign, cos_p): ([T; 3], T, T), scale: T) -> T {
    let Cap { a, dc, radius, cos_a, alpha } = *cap;
    let (u, v) = basis(p);
    let (au, av) = (dot(a, u), dot(a, v));
    let inside = cos_p > cos_a;
    // outside: the wedge of ψ that meets the cap, |ψ − ψ_a| ≤ Ψ with cos Ψ = √(cos²α − cos²β_p)/sin β_p,
    // taken as ψ = ψ_a + Ψ sin φ (the θ range closes like a square root at its edges)
    let sin_p = au.hypot(av);
    let (axis, half) = if sin_p > T::zero() { ((au / sin_p, av / sin_p), (((cos_a - cos_p) * (cos_a + cos_p)).max(T::zero()).sqrt() / sin_p).min(T::one()).acos()) } else { ((T::one(), T::zero()), T::zero()) };
    // −p inside the cap as well (`x` beside the sphere, the lobe pointing along its surface): every
    // half great circle from p meets the cap, up to θ = π
    let beside = cos_p < -cos_a;
    // the θ integral along e_ψ, given a·e_ψ = sin β_p cos(ψ − ψ_a): the rim where
    // A cos θ + B sin θ = cos α; θ from its least (0 inside, the near rim outside), graded from
    // there by s (outside by the larger of s and that least θ: the lobe's tail there is as wide
    // as its distance)
    let along = |big_b: T| {
        let (mut mid, spread) = (big_b.atan2(cos_p), (cos_a / cos_p.hypot(big_b)).min(T::one()).acos());
        if beside && mid < T::zero() {
            mid = mid + T::PI() + T::PI();
        }
        let from = if inside { T::zero() } else { (mid - spread).max(T::zero()) };
        let to = if beside { (mid + spread).min(T::PI()) } else { mid + spread };
        let mut around = T::zero();
        let mut node = |st: T, ct: T, w: T| {
            let toward_a = ct * cos_p + st * big_b;
            let root = (radius * radius - dc * dc * (T::one() - toward_a) * (T::one() + toward_a)).max(T::zero()).sqrt();
            let dist = (dc * toward_a - root).max(T::zero());
            around = around + w * light.emitted(root / radius) * exp_nonpositive(-light.sigma_t * dist) * light.phase_about(sign, (st, ct)) * st;
        };
        // a range longer than LOBE_REACH of its grading scales: the lobe's tail past LOBE_TAIL
        // graded from there by its own distance
        let tail = from + T::lit(LOBE_TAIL);
        if to > tail && to - from > T::lit(LOBE_REACH) * scale.max(from) {
            graded_from(scale, from, tail, &mut node);
            graded_from(scale, tail, to, &mut node);
        } else {
            graded_from(scale, from, to, &mut node);
        }
        around
    };
    let mut sum = T::zero();
    if inside {
        // as a disc holding the lobe's point (`flat_about_lobe`): the half of the directions
        // towards the rim's nearest point (−axis, the angle ε = α − β_p away) in the angle β of
        // the rim's tangent there (σ = D tan β, D = hypot(ε, min(s, the rim's half chord through
        // p))), the far half in ψ; in ψ alone the θ ranges towards the rim grow as ε/cos over
        // the last ε/α of the half
        let beta_p = sin_p.atan2(cos_p);
        // t with m = (t.1, −t.0) = −axis
        let t = (axis.1, -axis.0);
        let eps = alpha - beta_p;
        let half_chord = (eps * (alpha + beta_p)).max(T::zero()).sqrt();
        // (both halves are even about axis: their rules' nodes on one side, weights doubled)
        if eps > T::zero() {
            let reach = eps.hypot(scale.min(half_chord));
            for &(x, w) in &RADIAL {
                let (dir, _, dpsi) = line_point(eps, t, reach, T::lit(x) * T::FRAC_PI_2());
                sum = sum + T::lit(w + w) * T::FRAC_PI_2() * dpsi * along(sin_p * (dir.0 * axis.0 + dir.1 * axis.1));
            }
        }
        // ψ about axis: a·e_ψ = sin β_p cos ψ
        for &(cos, _, w) in &light.azimuths.even {
            sum = sum + w * along(sin_p * cos);
        }
        return sum;
    }
    if beside {
        // the half towards the rim's nearest point (axis) in the Mercator angle of the rim's
        // tangent there, as a flat emitter's wedge off it (the lobe's edge a step where its
        // chords start, ε/s wide in ψ before ±π/2); the far half in ψ (both even about axis)
        let t = (-axis.1, axis.0);
        mercator_rule(axis, [(axis.1, axis.0), (t.1, t.0)], |(c, sn), w| sum = sum + (w + w) * along(sin_p * (c * axis.0 + sn * axis.1)));
        for &(cos, _, w) in &light.azimuths.even {
            sum = sum + w * along(-sin_p * cos);
        }
        return sum;
    }
    // outside: ψ − ψ_a = Ψ sin φ, dψ = Ψ cos φ dφ, even in φ
    for &(cos, sin, wpsi) in &light.azimuths.even {
        let (_, c) = sin_cos_turns(half * sin);
        sum = sum + wpsi * half * cos * along(sin_p * c);
    }
    sum
}

/// The emitter as `S` takes it, its frame formed once per ray.
enum Shape<T> {
    Disc { c: [T; 3], frame: Frame<T>, radius: T },
    Parallelogram { p0: [T; 3], edges: ([T; 3], [T; 3]), frame: Frame<T> },
    Sphere { foot: SphereFoot<T>, radius: T },
}

/// Where a sphere lies from the ray's line: the vector from the centre's foot on the line to the
/// centre (`h` long) and the miss `h − R` to a few ulps of itself ([`sphere_miss`]), so that at
/// `x`, `along` past the foot, `c − x = to_centre − along·d` and `|c − x| − R = (miss (h + R) +
/// along²)/(|c − x| + R)` hold a grazing ray's gap to a few ulps, where `|c − (o + t d)|` rounded
/// holds it only to `ε·|c − x|` (in f32 1 % of a gap of 6e-6 at a radius of 0.625, where `S`
/// moves by 0.27 of the gap's relative change: docs/DESIGN.md §12).
#[derive(Clone, Copy)]
struct SphereFoot<T> {
    to_centre: [T; 3],
    h: T,
    miss: T,
}

impl<T: Real> SphereFoot<T> {
    /// `c − x` and `|c − x| − R` at `along` past the foot (`|c − x| − R` itself where `along²`
    /// overflows).
    fn at(&self, d: [T; 3], along: T, radius: T) -> ([T; 3], T) {
        let v = axpy(self.to_centre, -along, d);
        let length = length(v);
        let gap = (self.miss * (self.h + radius) + along * along) / (length + radius);
        (v, if gap.is_finite() { gap } else { length - radius })
    }
}

impl<T: Real> Shape<T> {
    /// `S(x)` at `x = o + t d`, `along = t − x_h` past the centre's foot.
    fn radiance<P: PhaseFunction<T>>(&self, light: &Light<'_, T, P>, x: [T; 3], along: T) -> T {
        match *self {
            Shape::Disc { c, frame, radius } => disc(light, x, c, frame, radius),
            Shape::Parallelogram { p0, edges, frame } => parallelogram(light, x, p0, edges, frame),
            Shape::Sphere { foot, radius } => {
                let (v, gap) = foot.at(light.d, along, radius);
                sphere(light, v, radius, gap)
            }
        }
    }

    /// A flat emitter's unit normal and the distances of a point `x` of its plane from the
    /// outline's nearest edge and from the next ([`Outline::distances`]); `None` for a sphere.
    fn outline_distances(&self, x: [T; 3]) -> Option<([T; 3], [T; 2])> {
        match *self {
            Shape::Disc { c, frame: (n, a1, a2), radius } => {
                let rel = sub(x, c);
                Some((n, Outline::Circle { c: (-dot(rel, a1), -dot(rel, a2)), radius }.distances()))
            }
            Shape::Parallelogram { p0, edges, frame } => {
                let (corners, foot) = parallelogram_corners(sub(x, p0), edges, frame);
                Some((frame.0, Outline::polygon_about(corners, foot).distances()))
            }
            Shape::Sphere { .. } => None,
        }
    }
}

impl<T, P> AreaScene<T, P>
where
    T: Real,
    P: PhaseFunction<T> + Clone,
{
    /// In-scattered radiance of the area light by the bounded method of [`outer`](self): the
    /// ray to [`BOUNDED_RAY_TOLERANCE`] in at most [`BOUNDED_RAY_PANELS`] panels, the emitter by
    /// fixed rules. Its cost has a fixed worst case (the shaders' budget) but no error control of
    /// the emitter's rules, which resolve a lobe narrower than their nodes' spacing only because
    /// they are placed about it: a phase lobe narrower than the emitter (the emitter is taken
    /// about the lobe's direction), a cosine lobe of emission (a sphere's `φ` and a flat
    /// emitter's `γ` are graded towards the normal).
    /// docs/DESIGN.md §12 gives its errors.
    pub fn in_scatter_bounded(&self) -> T {
        self.in_scatter_bounded_counted(T::lit(BOUNDED_RAY_TOLERANCE), BOUNDED_RAY_PANELS).0
    }

    /// [`AreaScene::in_scatter_bounded`] with the ray's tolerance and panel bound given, and the
    /// ray panels evaluated.
    pub fn in_scatter_bounded_counted(&self, tolerance: T, max_panels: usize) -> (T, usize) {
        if self.light.radiance == T::zero() || self.medium.sigma_s == T::zero() {
            return (T::zero(), 0);
        }
        let o = T::vec3_to_array(self.ray.origin);
        let d = normalize(T::vec3_to_array(self.ray.dir));
        let (t0, t1) = (self.ray.t_min, self.ray.t_max);
        let sigma_t = self.medium.sigma_t;
        let constant_phase = self.phase.is_isotropic().then(|| self.phase.eval(T::zero()));
        let power = self.light.emission.power();
        let emission_scale = (power > 1).then(|| T::lit(2.0) / T::from(power - 1).unwrap_or(T::one()).sqrt());
        let light = Light { d, sigma_t, radiance: self.light.radiance, power, emission_scale, phase: &self.phase, constant_phase, lobes: lobes(&self.phase), azimuths: Azimuths::new() };
        // the emitter, its centre and size, and where the ray's integrand changes its form
        let mut cuts = [T::nan(); 3];
        let (shape, centre, size) = match self.light.emitter {
            Emitter::Disc { center, normal, radius } => {
                let (c, n) = (T::vec3_to_array(center), normalize(T::vec3_to_array(normal)));
                cuts[0] = dot(sub(c, o), n) / dot(d, n);
                let (a1, a2) = basis(n);
                (Shape::Disc { c, frame: (n, a1, a2), radius }, c, radius)
            }
            Emitter::Rectangle { corner, edge_u, edge_v } => {
                let (p0, eu, ev) = (T::vec3_to_array(corner), T::vec3_to_array(edge_u), T::vec3_to_array(edge_v));
                let n = normalize(cross(eu, ev));
                cuts[0] = dot(sub(p0, o), n) / dot(d, n);
                let half = T::lit(0.5);
                let diagonal = [eu[0] + ev[0], eu[1] + ev[1], eu[2] + ev[2]];
                let a1 = normalize(eu);
                let shape = Shape::Parallelogram { p0, edges: (eu, ev), frame: (n, a1, cross(n, a1)) };
                (shape, axpy(p0, half, diagonal), half * length(diagonal).max(length(sub(eu, ev))))
            }
            Emitter::Sphere { center, radius } => {
                let c = T::vec3_to_array(center);
                // entry and exit: t² + 2bt + k = 0, its discriminant b² − k = R² − ρ² = −(ρ −
                // R)(ρ + R) from the centre's distance ρ to the ray's line and its miss (b² − k
                // itself cancels for a grazing ray)
                let oc = sub(o, c);
                let (b, k) = (dot(oc, d), dot(oc, oc) - radius * radius);
                let foot = match sphere_miss(o, T::vec3_to_array(self.ray.dir), c, radius) {
                    Some((h, m, miss)) => SphereFoot { to_centre: m.map(|x| h * x), h, miss },
                    None => {
                        let to_centre = axpy(oc, -b, d).map(|x| -x);
                        let h = length(to_centre);
                        SphereFoot { to_centre, h, miss: h - radius }
                    }
                };
                let disc = -foot.miss * (foot.h + radius);
                if disc > T::zero() {
                    let q = -b - disc.sqrt().copysign(b);
                    cuts = [q, k / q, T::nan()];
                }
                (Shape::Sphere { foot, radius }, c, radius)
            }
        };
        if !(size > T::zero()) {
            return (T::zero(), 0);
        }
        let x_h = dot(sub(centre, o), d);
        let h = length(sub(sub(centre, o), [x_h * d[0], x_h * d[1], x_h * d[2]]));
        let h_eff = h.hypot(size);
        // past the emitter's far side the extinction from t0 has grown by −ln ε more than
        // anywhere it is seen from nearer
        let t_end = if sigma_t > T::zero() { t1.min(t0 + length(sub(centre, axpy(o, t0, d))) + size - T::epsilon().ln() / sigma_t) } else { t1 };
        let theta = |t: T| if t.is_finite() { (t - x_h).atan2(h_eff) } else { T::FRAC_PI_2() };
        // a flat emitter's plane crossed δ from an edge in a phase lobe of scale s < 1: on its
        // emitting side S changes over the distance at which the lobe reaches δ, where a panel
        // ends ([`CROSSING_REACH`]); for the nearest edge and the next (a crossing on an edge by
        // a corner), unless the θ map's own scale h' is shorter
        let crossing = cuts[0];
        let s = light.lobes.iter().flatten().fold(T::one(), |s, &(_, scale)| s.min(scale));
        if let Some((n, distances)) = shape.outline_distances(axpy(o, crossing, d)).filter(|_| s < T::one() && crossing >= t0 && crossing <= t_end) {
            let front = if dot(d, n) < T::zero() { -T::one() } else { T::one() };
            for (cut, delta) in cuts[1..].iter_mut().zip(distances) {
                let reach = T::lit(CROSSING_REACH) * delta / s;
                if reach < h_eff {
                    *cut = crossing + front * reach;
                }
            }
        }
        // the cuts within the segment (outside it, or none: its start, which the edges skip)
        let mut inside = [x_h, cuts[0], cuts[1], cuts[2]].map(|t| theta(if t >= t0 && t <= t_end { t } else { t0 }));
        let (edges, n): ([T; 6], usize) = edges_between(theta(t0), theta(t_end), &mut inside);
        let mut integrand = |th: T| {
            let (s, c) = sin_cos_turns(th);
            let along = h_eff * s / c;
            h_eff / (c * c) * exp_nonpositive(-sigma_t * ((x_h - t0) + along).max(T::zero())) * shape.radiance(&light, axpy(o, x_h + along, d), along)
        };
        let (value, panels) = adaptive(&GAUSS_KRONROD_15, &mut integrand, &edges[..=n], tolerance, max_panels);
        (self.medium.sigma_s * value, panels)
    }
}

