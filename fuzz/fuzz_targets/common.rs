//! Decoding fuzz bytes into scenes, shared by the targets.

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
