//! Deterministic generators of hard predicate inputs, shared by the tests, the
//! proptest strategies, the benchmarks and the speed-against-error report.
//!
//! Each generator draws one case of a predicate's input from an
//! [`InputClass`] with a [`SplitMix64`] stream, so a seed names a case set
//! exactly on every platform. Nothing here allocates.
//!
//! ```
//! use exactray::testing::{orient3d_case, InputClass, SplitMix64};
//! let mut rng = SplitMix64::new(7);
//! for class in InputClass::ALL {
//!     let [a, b, c, d] = orient3d_case(class, &mut rng);
//!     let _ = exactray::predicates::orient3d(a, b, c, d);
//! }
//! ```

use glam::{DVec2, DVec3};

/// A family of inputs, from ordinary to adversarial.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum InputClass {
    /// Every coordinate uniform in `[-1, 1)`.
    Uniform,
    /// An almost degenerate configuration (collinear, coplanar, cocircular,
    /// cospherical) rounded to `f64`, sometimes moved by a few ulps more.
    NearDegenerate,
    /// An exactly degenerate configuration on dyadic coordinates, repeated
    /// points included: the exact sign is zero.
    Degenerate,
    /// Uniform, near-degenerate and degenerate configurations scaled by
    /// `2^-k` so that products underflow; some coordinates are subnormal.
    Tiny,
    /// The same configurations scaled by `2^k` so that products overflow
    /// (coordinates stay below `2^1020`, so differences are finite).
    Huge,
    /// Magnitudes near `1e-300` beside `1e+300` in one case, including huge
    /// coordinates that cancel exactly so that tiny offsets decide the sign.
    Mixed,
}

impl InputClass {
    /// Every class, in the order the report lists them.
    pub const ALL: [InputClass; 6] = [
        InputClass::Uniform,
        InputClass::NearDegenerate,
        InputClass::Degenerate,
        InputClass::Tiny,
        InputClass::Huge,
        InputClass::Mixed,
    ];

    /// The class's name in reports: lower case with hyphens.
    pub fn name(self) -> &'static str {
        match self {
            InputClass::Uniform => "uniform",
            InputClass::NearDegenerate => "near-degenerate",
            InputClass::Degenerate => "degenerate",
            InputClass::Tiny => "tiny",
            InputClass::Huge => "huge",
            InputClass::Mixed => "mixed",
        }
    }
}

/// Vigna's SplitMix64: a tiny, fast pseudo-random generator whose stream is
/// fixed by its seed on every platform.
#[derive(Clone, Debug)]
pub struct SplitMix64 {
    state: u64,
}

impl SplitMix64 {
    /// A generator whose stream is determined by `seed`.
    pub fn new(seed: u64) -> Self {
        SplitMix64 { state: seed }
    }

    /// The stream of one `(family, inputs)` pair of a report or a
    /// benchmark (`("orient2d", "uniform")`): seeded by the FNV-1a hash of
    /// `family/inputs`, so it is fixed, and independent of which other
    /// streams are drawn.
    ///
    /// ```
    /// use exactray::testing::SplitMix64;
    /// let mut a = SplitMix64::for_inputs("ray_sphere", "far");
    /// let mut b = SplitMix64::for_inputs("ray_sphere", "far");
    /// assert_eq!(a.next_u64(), b.next_u64());
    /// ```
    pub fn for_inputs(family: &str, inputs: &str) -> Self {
        Self::for_parts(family.as_bytes(), [inputs.as_bytes()])
    }

    /// [`for_inputs`](Self::for_inputs) with `inputs` the concatenation of
    /// `parts`.
    pub(super) fn for_parts<const N: usize>(family: &[u8], parts: [&[u8]; N]) -> Self {
        let seed = family
            .iter()
            .chain(b"/")
            .chain(parts.iter().flat_map(|p| p.iter()))
            .fold(0xcbf2_9ce4_8422_2325u64, |h, &b| {
                (h ^ b as u64).wrapping_mul(0x0100_0000_01b3)
            });
        SplitMix64::new(seed)
    }

    /// The next 64 random bits.
    pub fn next_u64(&mut self) -> u64 {
        self.state = self.state.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.state;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }

    /// A uniform `f64` in `[0, 1)`, a multiple of `2^-53`.
    pub fn next_f64(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 * (1.0 / (1u64 << 53) as f64)
    }

    /// Uniform in `[-1, 1)`.
    pub(super) fn signed(&mut self) -> f64 {
        2.0 * self.next_f64() - 1.0
    }

    /// Uniform integer in `lo..=hi`.
    pub(super) fn int(&mut self, lo: i64, hi: i64) -> i64 {
        let span = (hi - lo + 1) as u128;
        lo + ((self.next_u64() as u128 * span) >> 64) as i64
    }

    /// `true` with probability `1 / n`.
    fn one_in(&mut self, n: i64) -> bool {
        self.int(1, n) == 1
    }
}

/// Orientation input `a, b, c`: collinear ones for the degenerate classes.
pub fn orient2d_case(class: InputClass, rng: &mut SplitMix64) -> [DVec2; 3] {
    case::<2, 3>(class, rng, Shape::Flat).map(DVec2::from_array)
}

/// Orientation input `a, b, c, d`: coplanar ones (sometimes with a collinear
/// triangle) for the degenerate classes.
pub fn orient3d_case(class: InputClass, rng: &mut SplitMix64) -> [DVec3; 4] {
    case::<3, 4>(class, rng, Shape::Flat).map(DVec3::from_array)
}

/// In-circle input `a, b, c, d`: cocircular ones for the degenerate classes.
pub fn incircle_case(class: InputClass, rng: &mut SplitMix64) -> [DVec2; 4] {
    case::<2, 4>(class, rng, Shape::Round).map(DVec2::from_array)
}

/// In-sphere input `a, b, c, d, e`: cospherical ones for the degenerate
/// classes.
pub fn insphere_case(class: InputClass, rng: &mut SplitMix64) -> [DVec3; 5] {
    case::<3, 5>(class, rng, Shape::Round).map(DVec3::from_array)
}

/// Plane-side input `x0, x1, x2, p, q`: for the degenerate classes `p` and
/// `q` lie on (or next to) the plane of the triangle, or `q` lies anywhere.
pub fn plane_side_case(class: InputClass, rng: &mut SplitMix64) -> [DVec3; 5] {
    case::<3, 5>(class, rng, Shape::Flat).map(DVec3::from_array)
}

/// What makes a configuration degenerate: the points after the first `D`
/// lying on the flat the first `D` span, or every point on one sphere.
#[derive(Clone, Copy)]
enum Shape {
    Flat,
    Round,
}

/// How close to degenerate a configuration at unit scale is.
#[derive(Clone, Copy, PartialEq)]
enum Closeness {
    Uniform,
    Near,
    Exact,
}

type Points<const D: usize, const N: usize> = [[f64; D]; N];

fn case<const D: usize, const N: usize>(
    class: InputClass,
    rng: &mut SplitMix64,
    shape: Shape,
) -> Points<D, N> {
    match class {
        InputClass::Uniform => unit_case(Closeness::Uniform, shape, rng),
        InputClass::NearDegenerate => unit_case(Closeness::Near, shape, rng),
        InputClass::Degenerate => unit_case(Closeness::Exact, shape, rng),
        InputClass::Tiny => {
            // Around 2^-540 the determinant's products underflow; beyond
            // 2^-1000 the coordinates themselves go subnormal.
            let k = if rng.one_in(4) {
                rng.int(1000, 1064)
            } else {
                rng.int(520, 560)
            };
            let pts = unit_case(any_closeness(rng), shape, rng);
            pts.map(|p| p.map(|x| scale(x, -k)))
        }
        InputClass::Huge => {
            let k = rng.int(520, 1000);
            let pts = unit_case(any_closeness(rng), shape, rng);
            pts.map(|p| p.map(|x| scale(x, k)))
        }
        InputClass::Mixed => match rng.int(0, 2) {
            0 => [[0.0; D]; N].map(|p| p.map(|_| scale(rng.signed(), rng.int(-1000, 1000)))),
            1 => cancelling(shape, rng),
            _ => {
                // Scaling each axis by its own power of two keeps orientations
                // near-degenerate while mixing magnitudes within every point.
                let mut pts = unit_case(Closeness::Near, shape, rng);
                for k in 0..D {
                    let e = rng.int(-1000, 1000);
                    pts.iter_mut().for_each(|p| p[k] = scale(p[k], e));
                }
                pts
            }
        },
    }
}

fn any_closeness(rng: &mut SplitMix64) -> Closeness {
    match rng.int(0, 3) {
        0 => Closeness::Uniform,
        1 => Closeness::Exact,
        _ => Closeness::Near,
    }
}

/// An exactly degenerate configuration scaled up to around `2^1000` and moved
/// so that one point sits at the origin, which is then nudged by offsets near
/// `2^-1000`: the huge terms cancel exactly and the tiny ones decide the sign.
fn cancelling<const D: usize, const N: usize>(shape: Shape, rng: &mut SplitMix64) -> Points<D, N> {
    let mut pts = unit_case(Closeness::Exact, shape, rng);
    let i = rng.int(0, N as i64 - 1) as usize;
    let origin = pts[i];
    let k = rng.int(400, 1000);
    for p in pts.iter_mut() {
        for (x, o) in p.iter_mut().zip(origin) {
            *x = scale(*x - o, k);
        }
    }
    for x in pts[i].iter_mut() {
        *x = if rng.one_in(6) {
            0.0
        } else {
            scale(rng.signed(), -rng.int(900, 1070))
        };
    }
    pts
}

fn unit_case<const D: usize, const N: usize>(
    closeness: Closeness,
    shape: Shape,
    rng: &mut SplitMix64,
) -> Points<D, N> {
    let mut pts = match (closeness, shape) {
        (Closeness::Uniform, _) => [[0.0; D]; N].map(|p| p.map(|_| rng.signed())),
        (_, Shape::Flat) => on_flat(closeness == Closeness::Exact, rng),
        (_, Shape::Round) => on_sphere(closeness == Closeness::Exact, rng),
    };
    if closeness == Closeness::Near && !rng.one_in(4) {
        let i = rng.int(0, N as i64 - 1) as usize;
        pts[i] = pts[i].map(|x| step_ulps(x, rng.int(-3, 3)));
    }
    pts
}

/// The first `D` points free, the rest affine combinations of them. With
/// `exact` every coordinate is a small multiple of `2^-9`, so the
/// combinations are exact; otherwise they are rounded.
fn on_flat<const D: usize, const N: usize>(exact: bool, rng: &mut SplitMix64) -> Points<D, N> {
    let mut pts = [[0.0; D]; N];
    let weight = |rng: &mut SplitMix64| {
        if exact {
            rng.int(-16, 16) as f64 / 8.0
        } else {
            1.5 * rng.signed()
        }
    };
    for i in 0..N {
        let dependent = i >= D || (exact && i == D - 1 && rng.one_in(8));
        if !dependent {
            pts[i] = pts[i].map(|_| {
                if exact {
                    rng.int(-64, 63) as f64 / 64.0
                } else {
                    rng.signed()
                }
            });
        } else if i > D && rng.one_in(3) {
            // A second query point anywhere, for plane-side: only the first
            // decides that the case is degenerate.
            pts[i] = pts[i].map(|_| rng.signed());
        } else {
            let mut p = pts[0];
            for j in 1..D.min(i) {
                let w = weight(rng);
                for k in 0..D {
                    p[k] += w * (pts[j][k] - pts[0][k]);
                }
            }
            pts[i] = p;
        }
    }
    pts
}

/// Every point on one circle or sphere. With `exact` they are lattice points
/// of radius 65 scaled by `2^-7` around a centre on the `2^-8` grid, repeats
/// included; otherwise rational points of the unit sphere, scaled, rounded.
fn on_sphere<const D: usize, const N: usize>(exact: bool, rng: &mut SplitMix64) -> Points<D, N> {
    let mut pts = [[0.0; D]; N];
    let (centre, radius) = if exact {
        (
            [0.0; D].map(|_| rng.int(-128, 127) as f64 / 256.0),
            1.0 / 128.0,
        )
    } else {
        ([0.0; D].map(|_| rng.signed()), 0.25 + 0.75 * rng.next_f64())
    };
    for i in 0..N {
        let p = if exact && i > 0 && rng.one_in(10) {
            pts[rng.int(0, i as i64 - 1) as usize]
        } else {
            let dir = if exact {
                lattice_on_sphere::<D>(rng)
            } else {
                rational_on_sphere::<D>(rng)
            };
            core::array::from_fn(|k| centre[k] + radius * dir[k])
        };
        pts[i] = p;
    }
    pts
}

/// A random integer point with `|p|^2 = 65^2` (65 = 5 * 13 has many).
fn lattice_on_sphere<const D: usize>(rng: &mut SplitMix64) -> [f64; D] {
    const R: i64 = 65;
    loop {
        let mut p = [0.0; D];
        let mut rest = R * R;
        for x in p.iter_mut().take(D - 1) {
            let v = rng.int(-R, R);
            rest -= v * v;
            *x = v as f64;
        }
        if rest >= 0 {
            let root = (rest as u64).isqrt();
            if root * root == rest as u64 {
                p[D - 1] = if rng.one_in(2) {
                    root as f64
                } else {
                    -(root as f64)
                };
                // The solved-for coordinate would otherwise always be last.
                p.rotate_left(rng.int(0, D as i64 - 1) as usize);
                return p;
            }
        }
    }
}

/// Inverse stereographic projection of a random `u`: the point
/// `(2u, 1 - |u|^2) / (1 + |u|^2)` is on the unit sphere before rounding.
fn rational_on_sphere<const D: usize>(rng: &mut SplitMix64) -> [f64; D] {
    let u: [f64; D] = core::array::from_fn(|k| if k + 1 < D { rng.signed() } else { 0.0 });
    let s: f64 = u.iter().map(|x| x * x).sum();
    let mut p = u.map(|x| 2.0 * x / (1.0 + s));
    p[D - 1] = (1.0 - s) / (1.0 + s);
    if rng.one_in(2) {
        p[D - 1] = -p[D - 1];
    }
    p
}

/// `x * 2^k`, rounded once, for `|k| <= 2044`.
pub(super) fn scale(x: f64, k: i64) -> f64 {
    // Splitting the power keeps the first product exact for any input this
    // module scales, so only the last one rounds (into the subnormals).
    x * pow2(k / 2) * pow2(k - k / 2)
}

/// `2^k` for `-1022 <= k <= 1023`.
pub(super) fn pow2(k: i64) -> f64 {
    f64::from_bits(((k + 1023) as u64) << 52)
}

/// The float `n` representable steps away from `x` (negative `n` steps down),
/// crossing zero as the number line does. Saturates at the ends of the
/// ordering; a step past the largest finite value gives an infinity, which
/// callers that need finite values must avoid.
///
/// ```
/// use exactray::testing::step_ulps;
/// assert_eq!(step_ulps(1.0, 1), 1.0 + f64::EPSILON);
/// assert_eq!(step_ulps(0.0, -1), -f64::from_bits(1));
/// ```
pub fn step_ulps(x: f64, n: i64) -> f64 {
    // Map floats onto integers monotonically, -0.0 and 0.0 both to 0, so
    // stepping crosses zero correctly.
    let bits = x.to_bits() as i64;
    let ordered = if bits < 0 {
        i64::MIN.wrapping_sub(bits)
    } else {
        bits
    };
    let moved = ordered.saturating_add(n);
    f64::from_bits(if moved < 0 {
        i64::MIN.wrapping_sub(moved)
    } else {
        moved
    } as u64)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn helpers() {
        assert_eq!(scale(1.0, -1074), f64::from_bits(1));
        assert_eq!(scale(3.0, 1000), 3.0 * pow2(500) * pow2(500));
        assert_eq!(step_ulps(0.0, -1), -f64::from_bits(1));
        assert_eq!(step_ulps(-f64::from_bits(1), 2), f64::from_bits(1));
        assert_eq!(step_ulps(1.0, 1), 1.0 + f64::EPSILON);
    }

    #[test]
    fn bounded_and_finite() {
        let mut rng = SplitMix64::new(1);
        for class in InputClass::ALL {
            for _ in 0..2000 {
                let pts = insphere_case(class, &mut rng);
                let q = incircle_case(class, &mut rng);
                assert!(pts.iter().all(|p| p.abs().max_element() <= pow2(1020)));
                assert!(q.iter().all(|p| p.abs().max_element() <= pow2(1020)));
            }
        }
    }
}
