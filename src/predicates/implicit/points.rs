//! Points constructed from input points and never rounded: the line–plane
//! intersection [`Lpi`], the three-plane intersection [`Tpi`] and the
//! intersection of two lines in the plane [`Ssi`].
//!
//! A constructed point keeps the input points that define it. Its
//! construction decides exactly that they define one point (a typed error
//! otherwise) and keeps the exact sign of its homogeneous weight, which
//! every predicate on it needs.

use super::approx::{self, LpiCache, SsiCache, TpiCache};
use super::exact;
use crate::arith::exponent::scale_pow2;
use crate::arith::sparse_sum::diff;
use crate::error::InputError;
use crate::point::{IntoDVec2, IntoDVec3};
use crate::predicates::sparse;
use crate::predicates::{check_finite2, check_finite3};
use crate::sign::Sign;
use glam::{DVec2, DVec3};

/// The point where the line through `p` and `q` meets the plane through
/// `r`, `s` and `t`, kept as those five points.
///
/// With `n = (s - r) x (t - r)`, `D = n . (q - p)` and `P = n . (p - r)`,
/// the point is `X = p - (P / D) (q - p)`: relative to an origin `o`, its
/// homogeneous coordinates are `D (X - o) = D (p - o) - P (q - p)`, of
/// degree 4 in the input coordinates, over the weight `D`, of degree 3.
///
/// ```
/// use exactray::predicates::Lpi;
/// // The z axis meets the plane z = 1/3 at (0, 0, 1/3), which f64 cannot hold.
/// let third = 1.0 / 3.0;
/// let x = Lpi::new([0.0, 0.0, 0.0], [0.0, 0.0, 1.0],
///                  [1.0, 0.0, third], [0.0, 1.0, third], [0.0, 0.0, third]).unwrap();
/// assert_eq!(x.line(), [glam::DVec3::ZERO, glam::DVec3::Z]);
/// // A line parallel to the plane is not one point.
/// assert!(Lpi::new([0.0; 3], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0], [1.0, 0.0, 1.0], [0.0, 1.0, 1.0]).is_err());
/// ```
#[derive(Clone, Copy, Debug)]
pub struct Lpi {
    pub(super) p: DVec3,
    pub(super) q: DVec3,
    pub(super) r: DVec3,
    pub(super) s: DVec3,
    pub(super) t: DVec3,
    /// The exact sign of `D`.
    pub(super) w: Sign,
    /// The filter's origin-free part.
    pub(super) cache: LpiCache,
}

/// Equal when defined by the same input points.
impl PartialEq for Lpi {
    fn eq(&self, o: &Lpi) -> bool {
        [self.p, self.q, self.r, self.s, self.t] == [o.p, o.q, o.r, o.s, o.t]
    }
}

impl Lpi {
    /// The intersection of the line through `p`, `q` with the plane through
    /// `r`, `s`, `t`.
    ///
    /// # Errors
    /// [`InputError::NonFinite`] for a NaN or infinite coordinate, naming
    /// the first such argument; [`InputError::NoUniqueIntersection`] when
    /// `D = det[s - r, t - r, q - p]` is exactly zero (the line is parallel
    /// to the plane or lies in it, `p == q`, or `r, s, t` are collinear),
    /// decided exactly.
    pub fn new(
        p: impl IntoDVec3,
        q: impl IntoDVec3,
        r: impl IntoDVec3,
        s: impl IntoDVec3,
        t: impl IntoDVec3,
    ) -> Result<Lpi, InputError> {
        let [p, q, r, s, t] = [
            p.into_dvec3(),
            q.into_dvec3(),
            r.into_dvec3(),
            s.into_dvec3(),
            t.into_dvec3(),
        ];
        check_finite3(&[("p", p), ("q", q), ("r", r), ("s", s), ("t", t)])?;
        let cache = approx::lpi_cache(p, q, r, s, t);
        let w = cache
            .weight_sign()
            .unwrap_or_else(|| det3_of_differences([(s, r), (t, r), (q, p)]));
        if w == Sign::Zero {
            return Err(InputError::NoUniqueIntersection {
                construction: "Lpi",
            });
        }
        Ok(Lpi {
            p,
            q,
            r,
            s,
            t,
            w,
            cache,
        })
    }

    /// The two points of the line, `[p, q]`.
    pub fn line(&self) -> [DVec3; 2] {
        [self.p, self.q]
    }

    /// The three points of the plane, `[r, s, t]`.
    pub fn plane(&self) -> [DVec3; 3] {
        [self.r, self.s, self.t]
    }

    /// The same construction on every input coordinate times `2^k`.
    pub(super) fn scaled(&self, k: i32) -> Lpi {
        let [p, q, r, s, t] = [self.p, self.q, self.r, self.s, self.t].map(|v| scale3(v, k));
        Lpi {
            p,
            q,
            r,
            s,
            t,
            w: self.w,
            cache: approx::lpi_cache(p, q, r, s, t),
        }
    }
}

/// The common point of three planes, each through three points, kept as
/// those nine points.
///
/// With `n_i` the normal `(i1 - i0) x (i2 - i0)` of plane `i` and `W =
/// det[n_u, n_v, n_w]`, relative to an origin `o` the point's homogeneous
/// coordinates are `W (X - o) = h_u (n_v x n_w) + h_v (n_w x n_u) + h_w
/// (n_u x n_v)`, `h_i = n_i . (i0 - o)`: degree 7 in the input
/// coordinates, over the weight `W`, of degree 6.
///
/// ```
/// use exactray::predicates::Tpi;
/// let x = Tpi::new(
///     [[1.0, 0.0, 0.0], [1.0, 1.0, 0.0], [1.0, 0.0, 1.0]], // x = 1
///     [[0.0, 2.0, 0.0], [0.0, 2.0, 1.0], [1.0, 2.0, 0.0]], // y = 2
///     [[0.0, 0.0, 3.0], [1.0, 0.0, 3.0], [0.0, 1.0, 3.0]], // z = 3
/// );
/// assert!(x.is_ok());
/// ```
#[derive(Clone, Copy, Debug)]
pub struct Tpi {
    pub(super) planes: [[DVec3; 3]; 3],
    /// The exact sign of `W`.
    pub(super) w: Sign,
    /// The filter's origin-free part.
    pub(super) cache: TpiCache,
}

/// Equal when defined by the same input points.
impl PartialEq for Tpi {
    fn eq(&self, o: &Tpi) -> bool {
        self.planes == o.planes
    }
}

impl Tpi {
    /// The common point of the planes through `u`, through `v` and through
    /// `w`.
    ///
    /// # Errors
    /// [`InputError::NonFinite`] for a NaN or infinite coordinate, naming
    /// the plane (`"u"`, `"v"` or `"w"`); [`InputError::NoUniqueIntersection`]
    /// when `W` is exactly zero (two planes parallel or equal, the three
    /// through one line, or a plane's three points collinear), decided
    /// exactly.
    pub fn new<P: IntoDVec3>(u: [P; 3], v: [P; 3], w: [P; 3]) -> Result<Tpi, InputError> {
        let planes = [u, v, w].map(|plane| plane.map(|p| p.into_dvec3()));
        for (name, plane) in ["u", "v", "w"].into_iter().zip(&planes) {
            check_finite3(&[(name, plane[0]), (name, plane[1]), (name, plane[2])])?;
        }
        let mut x = Tpi {
            planes,
            w: Sign::Zero,
            cache: approx::tpi_cache(&planes),
        };
        x.w = x
            .cache
            .weight_sign()
            .unwrap_or_else(|| exact::tpi_weight_sign(&x.planes));
        if x.w == Sign::Zero {
            return Err(InputError::NoUniqueIntersection {
                construction: "Tpi",
            });
        }
        Ok(x)
    }

    /// The three planes, each as its three points.
    pub fn planes(&self) -> [[DVec3; 3]; 3] {
        self.planes
    }

    pub(super) fn scaled(&self, k: i32) -> Tpi {
        let planes = self.planes.map(|plane| plane.map(|v| scale3(v, k)));
        Tpi {
            planes,
            w: self.w,
            cache: approx::tpi_cache(&planes),
        }
    }
}

/// The point where the line through `p` and `q` meets the line through
/// `r` and `s`, in the plane, kept as those four points (the crossing of
/// two segments, when it lies on both).
///
/// With `e = q - p`, `f = s - r`, `D = e x f` and `T = (r - p) x f`, the
/// point is `p + (T / D) e`: relative to an origin `o`, its homogeneous
/// coordinates are `D (X - o) = D (p - o) + T e`, of degree 3 in the input
/// coordinates, over the weight `D`, of degree 2.
///
/// ```
/// use exactray::predicates::Ssi;
/// assert!(Ssi::new([0.0, 0.0], [1.0, 1.0], [0.0, 1.0], [1.0, 0.0]).is_ok());
/// // Parallel lines.
/// assert!(Ssi::new([0.0, 0.0], [1.0, 1.0], [0.0, 1.0], [1.0, 2.0]).is_err());
/// ```
#[derive(Clone, Copy, Debug)]
pub struct Ssi {
    pub(super) p: DVec2,
    pub(super) q: DVec2,
    pub(super) r: DVec2,
    pub(super) s: DVec2,
    /// The exact sign of `D`.
    pub(super) w: Sign,
    /// The filter's origin-free part.
    pub(super) cache: SsiCache,
}

/// Equal when defined by the same input points.
impl PartialEq for Ssi {
    fn eq(&self, o: &Ssi) -> bool {
        [self.p, self.q, self.r, self.s] == [o.p, o.q, o.r, o.s]
    }
}

impl Ssi {
    /// The intersection of the line through `p`, `q` with the line through
    /// `r`, `s`.
    ///
    /// # Errors
    /// [`InputError::NonFinite`] for a NaN or infinite coordinate, naming
    /// the first such argument; [`InputError::NoUniqueIntersection`] when
    /// `(q - p) x (s - r)` is exactly zero (parallel or equal lines, `p ==
    /// q` or `r == s`), decided exactly.
    pub fn new(
        p: impl IntoDVec2,
        q: impl IntoDVec2,
        r: impl IntoDVec2,
        s: impl IntoDVec2,
    ) -> Result<Ssi, InputError> {
        let [p, q, r, s] = [
            p.into_dvec2(),
            q.into_dvec2(),
            r.into_dvec2(),
            s.into_dvec2(),
        ];
        check_finite2(&[("p", p), ("q", q), ("r", r), ("s", s)])?;
        let cache = approx::ssi_cache(p, q, r, s);
        let w = cache
            .weight_sign()
            .unwrap_or_else(|| cross_of_differences((q, p), (s, r)));
        if w == Sign::Zero {
            return Err(InputError::NoUniqueIntersection {
                construction: "Ssi",
            });
        }
        Ok(Ssi {
            p,
            q,
            r,
            s,
            w,
            cache,
        })
    }

    /// The two lines, each as its two points: `[[p, q], [r, s]]`.
    pub fn lines(&self) -> [[DVec2; 2]; 2] {
        [[self.p, self.q], [self.r, self.s]]
    }

    pub(super) fn scaled(&self, k: i32) -> Ssi {
        let [p, q, r, s] = [self.p, self.q, self.r, self.s].map(|v| scale2(v, k));
        Ssi {
            p,
            q,
            r,
            s,
            w: self.w,
            cache: approx::ssi_cache(p, q, r, s),
        }
    }
}

pub(super) fn scale2(v: DVec2, k: i32) -> DVec2 {
    DVec2::new(scale_pow2(v.x, k), scale_pow2(v.y, k))
}

pub(super) fn scale3(v: DVec3, k: i32) -> DVec3 {
    DVec3::new(scale_pow2(v.x, k), scale_pow2(v.y, k), scale_pow2(v.z, k))
}

/// The exact sign of `det[a0 - b0, a1 - b1, a2 - b2]` (finite input), by
/// the sparse exact terms (`predicates::sparse`), where the filter could
/// not tell.
fn det3_of_differences(rows: [(DVec3, DVec3); 3]) -> Sign {
    let d = rows.map(|(a, b)| [diff(a.x, b.x), diff(a.y, b.y), diff(a.z, b.z)]);
    sparse::det3(d[0], d[1], d[2]).unwrap_or_else(|| exact::det3_of_differences(rows))
}

/// The exact sign of `(a0 - b0) x (a1 - b1)` (finite input), where the
/// filter could not tell.
fn cross_of_differences(e: (DVec2, DVec2), f: (DVec2, DVec2)) -> Sign {
    let d = |(a, b): (DVec2, DVec2)| [diff(a.x, b.x), diff(a.y, b.y)];
    sparse::cross2_of(d(e), d(f)).unwrap_or_else(|| exact::cross_of_differences(e, f))
}
