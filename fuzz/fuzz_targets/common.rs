//! Decoding fuzz bytes into scenes, shared by the targets.
#![allow(dead_code, unused_macros)]

/// Reads numbers from the fuzz input: each takes 9 bytes, a mode byte and 8 payload bytes.
pub struct Reader<'a>(pub &'a [u8]);

impl Reader<'_> {
    fn take(&mut self) -> (u8, u64) {
        if self.0.len() < 9 {
            let mut buf = [0u8; 9];
            buf[..self.0.len()].copy_from_slice(self.0);
            self.0 = &[];
            return (buf[0], u64::from_le_bytes(buf[1..9].try_into().unwrap()));
        }
        let (head, rest) = self.0.split_at(9);
        self.0 = rest;
        (head[0], u64::from_le_bytes(head[1..9].try_into().unwrap()))
    }
    /// A number in `[lo, hi]` most of the time; raw bits or a special value otherwise.
    pub fn num(&mut self, lo: f64, hi: f64) -> f64 {
        let (mode, bits) = self.take();
        let unit = (bits >> 11) as f64 / (1u64 << 53) as f64;
        match mode % 16 {
            0 => f64::from_bits(bits),
            1 => [0.0, -0.0, 1.0, -1.0, f64::MIN_POSITIVE, 5e-324, f64::MAX, f64::INFINITY, f64::NAN, 1e-300, 1e300, f32::MAX as f64, f32::MIN_POSITIVE as f64, 1e-45][(bits % 14) as usize],
            2 => lo.signum() * (unit * 600.0 - 300.0).exp(),
            _ => lo + (hi - lo) * unit,
        }
    }
    /// A small integer.
    pub fn int(&mut self, n: u64) -> u64 {
        self.take().1 % n.max(1)
    }
}

/// A scene as the fuzzer's bytes give it, in f64 (each field may be anything).
#[derive(Clone, Copy, Debug)]
pub struct Raw {
    pub o: [f64; 3],
    pub d: [f64; 3],
    pub t0: f64,
    pub t1: f64,
    pub p: [f64; 3],
    pub i: f64,
    pub ss: f64,
    pub st: f64,
    pub light: u64,
    pub axis: [f64; 3],
    pub power: u64,
    pub ci: f64,
    pub co: f64,
    pub phase: u64,
    pub g1: f64,
    pub g2: f64,
    pub w: f64,
}

/// Reads one scene from the front of `data`.
pub fn decode(data: &[u8]) -> Raw {
    decode_from(&mut Reader(data))
}

/// Reads one scene from `r` (25 or 26 numbers of 9 bytes), leaving the rest.
pub fn decode_from(r: &mut Reader) -> Raw {
    let v3 = |r: &mut Reader, lo: f64, hi: f64| [r.num(lo, hi), r.num(lo, hi), r.num(lo, hi)];
    let o = v3(r, -100.0, 100.0);
    let d = v3(r, -1.0, 1.0);
    let t0 = r.num(-10.0, 10.0);
    let t1 = if r.int(5) == 0 { f64::INFINITY } else { t0 + r.num(0.0, 200.0).abs() };
    let p = v3(r, -100.0, 100.0);
    Raw {
        o,
        d,
        t0,
        t1,
        p,
        i: r.num(0.0, 1000.0),
        ss: r.num(0.0, 2.0),
        st: r.num(0.0, 50.0),
        light: r.int(3),
        axis: v3(r, -1.0, 1.0),
        power: r.int(20),
        ci: r.num(-1.0, 1.0),
        co: r.num(-1.0, 1.0),
        phase: r.int(6),
        g1: r.num(-0.99, 0.99),
        g2: r.num(-0.99, 0.99),
        w: r.num(0.0, 1.0),
    }
}

/// The light's distance from the ray line and its foot, in f64.
pub fn h_and_xh(raw: &Raw) -> (f64, f64) {
    // normalise as the kernel does: scaled by the largest component first
    let m = raw.d.iter().fold(0.0f64, |a, x| a.max(x.abs()));
    let s = raw.d.map(|x| x / m);
    let n = (s.iter().map(|x| x * x).sum::<f64>()).sqrt();
    let d = s.map(|x| x / n);
    let op = [raw.p[0] - raw.o[0], raw.p[1] - raw.o[1], raw.p[2] - raw.o[2]];
    let xh = op[0] * d[0] + op[1] * d[1] + op[2] * d[2];
    let perp = [xh * d[0] - op[0], xh * d[1] - op[1], xh * d[2] - op[2]];
    let pm = perp.iter().fold(0.0f64, |a, x| a.max(x.abs()));
    let h = if pm == 0.0 { 0.0 } else { pm * (perp.iter().map(|x| (x / pm) * (x / pm)).sum::<f64>()).sqrt() };
    (h, xh)
}

/// An upper bound of every phase function at the raw parameters.
pub fn p_max(raw: &Raw) -> f64 {
    let g = raw.g1.abs().max(raw.g2.abs()).min(0.999_999);
    3.0 * (1.0 + g) / (4.0 * std::f64::consts::PI * (1.0 - g) * (1.0 - g))
}

/// `(ray, light, medium, phase)` of a [`Raw`] scene in the given precision and glam vector.
macro_rules! scene_types {
    ($t:ty, $v:ident) => {{
        |raw: &Raw| {
            let v = |a: [f64; 3]| $v::new(a[0] as $t, a[1] as $t, a[2] as $t);
            let dist = match raw.light {
                0 => airlight::light::AnyDistribution::Omni,
                1 => airlight::light::AnyDistribution::TwoLobed(airlight::light::TwoLobed { axis: v(raw.axis), power: raw.power as u32 }),
                _ => airlight::light::AnyDistribution::SpotCone(airlight::light::SpotCone { axis: v(raw.axis), cos_inner: raw.ci as $t, cos_outer: raw.co as $t }),
            };
            let phase = match raw.phase {
                0 => airlight::phase::AnyPhase::Isotropic,
                1 => airlight::phase::AnyPhase::Rayleigh,
                2 => airlight::phase::AnyPhase::HenyeyGreenstein(airlight::phase::HenyeyGreenstein { g: raw.g1 as $t }),
                3 => airlight::phase::AnyPhase::Schlick(airlight::phase::Schlick { k: raw.g1 as $t }),
                4 => airlight::phase::AnyPhase::CornetteShanks(airlight::phase::CornetteShanks { g: raw.g1 as $t }),
                _ => airlight::phase::AnyPhase::TwoLobeHenyeyGreenstein(airlight::phase::TwoLobeHenyeyGreenstein { g1: raw.g1 as $t, g2: raw.g2 as $t, w: raw.w as $t }),
            };
            (
                airlight::Ray { origin: v(raw.o), dir: v(raw.d), t_min: raw.t0 as $t, t_max: raw.t1 as $t },
                airlight::PointLight { position: v(raw.p), intensity: raw.i as $t, distribution: dist },
                airlight::Medium { sigma_s: raw.ss as $t, sigma_t: raw.st as $t },
                phase,
            )
        }
    }};
}

