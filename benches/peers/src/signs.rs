//! The predicates' signs as exactray reports them (`Sign::as_i8`: `1`,
//! `0`, `-1`), computed by the textbook `f64` formulas, by the `robust`
//! crate (Shewchuk's adaptive predicates) and by the crates that claim
//! exact predicates (`arithmetica`, `axiolid-predicates`, `apfp`), negated
//! where their convention is the opposite of exactray's, with NaN (or a
//! peer's refusal to answer) as [`NAN`].

use glam::DVec3;

/// What a float method's NaN counts as: never equal to an exact sign.
pub const NAN: i8 = i8::MIN;

/// The sign of a float result, with NaN as [`NAN`].
#[inline]
pub fn sign_of(v: f64) -> i8 {
    if v > 0.0 {
        1
    } else if v < 0.0 {
        -1
    } else if v == 0.0 {
        0
    } else {
        NAN
    }
}

/// Minus [`sign_of`], for peers whose convention is the opposite of ours.
#[inline]
pub fn minus_sign_of(v: f64) -> i8 {
    negate(sign_of(v))
}

/// Minus a sign, with [`NAN`] kept.
#[inline]
pub fn negate(s: i8) -> i8 {
    match s {
        NAN => NAN,
        s => -s,
    }
}

/// `plane_side` from two orient3d signs: `1` same side, `-1` opposite
/// sides, `0` either on the plane, [`NAN`] if either is.
#[inline(always)]
pub fn plane_side_by(
    orient3d: fn(DVec3, DVec3, DVec3, DVec3) -> i8,
    &[x0, x1, x2, p, q]: &[DVec3; 5],
) -> i8 {
    match (orient3d(x0, x1, x2, p), orient3d(x0, x1, x2, q)) {
        (NAN, _) | (_, NAN) => NAN,
        (s, t) => s * t,
    }
}

/// The textbook formulas, in plain `f64`.
pub mod naive {
    use super::{minus_sign_of, sign_of};
    use glam::{DVec2, DVec3};

    /// The sign of `(b - a) x (c - a)`.
    #[inline]
    pub fn orient2d(&[a, b, c]: &[DVec2; 3]) -> i8 {
        sign_of((b - a).perp_dot(c - a))
    }

    /// The sign of `det[b - a, c - a, d - a]`.
    #[inline]
    pub fn orient3d(a: DVec3, b: DVec3, c: DVec3, d: DVec3) -> i8 {
        sign_of((b - a).dot((c - a).cross(d - a)))
    }

    /// Shewchuk's `incirclefast`, expanded along the lifted column.
    #[inline]
    pub fn incircle(&[a, b, c, d]: &[DVec2; 4]) -> i8 {
        let (ad, bd, cd) = (a - d, b - d, c - d);
        let det = ad.length_squared() * bd.perp_dot(cd)
            + bd.length_squared() * cd.perp_dot(ad)
            + cd.length_squared() * ad.perp_dot(bd);
        sign_of(det)
    }

    /// Shewchuk's `inspherefast`, negated.
    #[inline]
    pub fn insphere(&[a, b, c, d, e]: &[DVec3; 5]) -> i8 {
        let (ae, be, ce, de) = (a - e, b - e, c - e, d - e);
        let minor = |u: DVec3, v: DVec3| u.x * v.y - v.x * u.y;
        let (ab, bc, cd, da) = (minor(ae, be), minor(be, ce), minor(ce, de), minor(de, ae));
        let (ac, bd) = (minor(ae, ce), minor(be, de));
        let abc = ae.z * bc - be.z * ac + ce.z * ab;
        let bcd = be.z * cd - ce.z * bd + de.z * bc;
        let cda = ce.z * da + de.z * ac + ae.z * cd;
        let dab = de.z * ab + ae.z * bd + be.z * da;
        let det = (de.length_squared() * abc - ce.length_squared() * dab)
            + (be.length_squared() * cda - ae.length_squared() * bcd);
        minus_sign_of(det)
    }

    /// Two [`orient3d`] signs.
    #[inline]
    pub fn plane_side(c: &[DVec3; 5]) -> i8 {
        super::plane_side_by(orient3d, c)
    }
}

/// A module of calls of `robust`'s interface, from the crate `$krate`, in
/// exactray's conventions: the `robust` crate itself and exactray's
/// drop-in for it share them.
macro_rules! robust_calls {
    ($(#[$doc:meta])* $module:ident, $krate:ident) => {
        $(#[$doc])*
        pub mod $module {
            use super::{minus_sign_of, sign_of};
            use glam::{DVec2, DVec3};

            /// A point for the `robust` crate.
            #[inline]
            pub fn coord(p: DVec2) -> ::$krate::Coord<f64> {
                ::$krate::Coord { x: p.x, y: p.y }
            }

            /// A 3D point for the `robust` crate.
            #[inline]
            pub fn coord3(p: DVec3) -> ::$krate::Coord3D<f64> {
                ::$krate::Coord3D {
                    x: p.x,
                    y: p.y,
                    z: p.z,
                }
            }

            /// `robust::orient2d`.
            #[inline]
            pub fn orient2d(&[a, b, c]: &[DVec2; 3]) -> i8 {
                sign_of(::$krate::orient2d(coord(a), coord(b), coord(c)))
            }

            /// `robust::orient3d`, negated (Shewchuk's convention is minus CGAL's).
            #[inline]
            pub fn orient3d(a: DVec3, b: DVec3, c: DVec3, d: DVec3) -> i8 {
                minus_sign_of(::$krate::orient3d(
                    coord3(a),
                    coord3(b),
                    coord3(c),
                    coord3(d),
                ))
            }

            /// `robust::incircle`.
            #[inline]
            pub fn incircle(&[a, b, c, d]: &[DVec2; 4]) -> i8 {
                sign_of(::$krate::incircle(coord(a), coord(b), coord(c), coord(d)))
            }

            /// `robust::insphere`, negated.
            #[inline]
            pub fn insphere(p: &[DVec3; 5]) -> i8 {
                let [a, b, c, d, e] = p.map(coord3);
                minus_sign_of(::$krate::insphere(a, b, c, d, e))
            }

            /// Two [`orient3d`] signs.
            #[inline]
            pub fn plane_side(c: &[DVec3; 5]) -> i8 {
                super::plane_side_by(orient3d, c)
            }
        }
    };
}

robust_calls!(
    /// The `robust` crate's predicates, in exactray's conventions.
    robust,
    robust
);

robust_calls!(
    /// exactray's drop-in for `robust` (the workspace's `robust/`, exact
    /// for every finite input), in exactray's conventions.
    robust_drop_in,
    robust_drop_in
);

/// The `arithmetica` crate's predicates (exact for every finite input, by
/// its documentation), in exactray's conventions; its `Err` (a non-finite
/// coordinate) as [`NAN`].
pub mod arithmetica {
    use super::NAN;
    use glam::{DVec2, DVec3};

    #[inline]
    fn sign(s: Result<::arithmetica::Sign, ::arithmetica::NonFinite>) -> i8 {
        match s {
            Ok(::arithmetica::Sign::Positive) => 1,
            Ok(::arithmetica::Sign::Negative) => -1,
            Ok(::arithmetica::Sign::Zero) => 0,
            Err(_) => NAN,
        }
    }

    /// `arithmetica::orient2d`.
    #[inline]
    pub fn orient2d(&[a, b, c]: &[DVec2; 3]) -> i8 {
        sign(::arithmetica::orient2d(a.into(), b.into(), c.into()))
    }

    /// `arithmetica::orient3d`, negated (Shewchuk's convention).
    #[inline]
    pub fn orient3d(a: DVec3, b: DVec3, c: DVec3, d: DVec3) -> i8 {
        super::negate(sign(::arithmetica::orient3d(
            a.into(),
            b.into(),
            c.into(),
            d.into(),
        )))
    }

    /// `arithmetica::incircle`.
    #[inline]
    pub fn incircle(&[a, b, c, d]: &[DVec2; 4]) -> i8 {
        sign(::arithmetica::incircle(
            a.into(),
            b.into(),
            c.into(),
            d.into(),
        ))
    }

    /// `arithmetica::insphere`, negated (Shewchuk's convention).
    #[inline]
    pub fn insphere(p: &[DVec3; 5]) -> i8 {
        let [a, b, c, d, e] = p.map(<[f64; 3]>::from);
        super::negate(sign(::arithmetica::insphere(a, b, c, d, e)))
    }

    /// Two [`orient3d`] signs.
    #[inline]
    pub fn plane_side(c: &[DVec3; 5]) -> i8 {
        super::plane_side_by(orient3d, c)
    }
}

/// The `axiolid-predicates` crate's predicates (a filter, then expansion
/// arithmetic; a fixed-size dyadic fallback for orient3d), in exactray's
/// conventions; an `Uncertain` answer as [`NAN`].
pub mod axiolid {
    use super::NAN;
    use axiolid_core::{Point2, Point3};
    use axiolid_guarantees::{Certified, Sign};
    use glam::{DVec2, DVec3};

    #[inline]
    fn sign(c: Certified) -> i8 {
        match c.sign() {
            Some(Sign::Positive) => 1,
            Some(Sign::Negative) => -1,
            Some(Sign::Zero) => 0,
            // `Sign` is non-exhaustive; no other answer is a sign.
            Some(_) | None => NAN,
        }
    }

    #[inline]
    fn p2(p: DVec2) -> Point2 {
        Point2::new(p.x, p.y)
    }

    #[inline]
    fn p3(p: DVec3) -> Point3 {
        Point3::new(p.x, p.y, p.z)
    }

    /// `axiolid_predicates::orient2d`.
    #[inline]
    pub fn orient2d(&[a, b, c]: &[DVec2; 3]) -> i8 {
        sign(axiolid_predicates::orient2d(p2(a), p2(b), p2(c)))
    }

    /// `axiolid_predicates::orient3d`, negated (Shewchuk's convention).
    #[inline]
    pub fn orient3d(a: DVec3, b: DVec3, c: DVec3, d: DVec3) -> i8 {
        super::negate(sign(axiolid_predicates::orient3d(
            p3(a),
            p3(b),
            p3(c),
            p3(d),
        )))
    }

    /// `axiolid_predicates::incircle`.
    #[inline]
    pub fn incircle(&[a, b, c, d]: &[DVec2; 4]) -> i8 {
        sign(axiolid_predicates::incircle(p2(a), p2(b), p2(c), p2(d)))
    }

    /// `axiolid_predicates::insphere`, negated (Shewchuk's convention).
    #[inline]
    pub fn insphere(&[a, b, c, d, e]: &[DVec3; 5]) -> i8 {
        super::negate(sign(axiolid_predicates::insphere(
            p3(a),
            p3(b),
            p3(c),
            p3(d),
            p3(e),
        )))
    }

    /// Two [`orient3d`] signs.
    #[inline]
    pub fn plane_side(c: &[DVec3; 5]) -> i8 {
        super::plane_side_by(orient3d, c)
    }
}

/// The `apfp` crate: its `orient2d` and `incircle`, and its `apfp_signum!`
/// on the same determinants as exactray's `orient3d` and `insphere`, with
/// the coordinates as the expression's atoms (nothing rounded before it).
pub mod apfp {
    use ::apfp::geometry::Orientation;
    use ::apfp::geometry::f64::Coord;
    // `square` is named by the expansion of `apfp_signum!`.
    #[allow(unused_imports)]
    use ::apfp::{apfp_signum, square};
    use glam::{DVec2, DVec3};

    #[inline]
    fn sign(o: Orientation) -> i8 {
        match o {
            Orientation::CounterClockwise => 1,
            Orientation::Clockwise => -1,
            Orientation::CoLinear => 0,
        }
    }

    #[inline]
    fn coord(p: DVec2) -> Coord {
        Coord::new(p.x, p.y)
    }

    /// `apfp::geometry::f64::orient2d`.
    #[inline]
    pub fn orient2d(&[a, b, c]: &[DVec2; 3]) -> i8 {
        sign(::apfp::geometry::f64::orient2d(
            &coord(a),
            &coord(b),
            &coord(c),
        ))
    }

    /// `apfp_signum!` on `det[b - a, c - a, d - a]`.
    #[inline]
    pub fn orient3d(a: DVec3, b: DVec3, c: DVec3, d: DVec3) -> i8 {
        let [ax, ay, az] = a.to_array();
        let [bx, by, bz] = b.to_array();
        let [cx, cy, cz] = c.to_array();
        let [dx, dy, dz] = d.to_array();
        apfp_signum!(
            (bx - ax) * ((cy - ay) * (dz - az) - (cz - az) * (dy - ay))
                - (by - ay) * ((cx - ax) * (dz - az) - (cz - az) * (dx - ax))
                + (bz - az) * ((cx - ax) * (dy - ay) - (cy - ay) * (dx - ax))
        ) as i8
    }

    /// `apfp::geometry::f64::incircle`.
    #[inline]
    pub fn incircle(&[a, b, c, d]: &[DVec2; 4]) -> i8 {
        sign(::apfp::geometry::f64::incircle(
            &coord(a),
            &coord(b),
            &coord(c),
            &coord(d),
        ))
    }

    /// `apfp_signum!` on the lifted determinant of Shewchuk's `insphere`
    /// (its expansion along the lifted column, as `naive::insphere`),
    /// negated.
    #[inline]
    pub fn insphere(&[a, b, c, d, e]: &[DVec3; 5]) -> i8 {
        let [ax, ay, az] = a.to_array();
        let [bx, by, bz] = b.to_array();
        let [cx, cy, cz] = c.to_array();
        let [dx, dy, dz] = d.to_array();
        let [ex, ey, ez] = e.to_array();
        -(apfp_signum!(
            (square((dx - ex)) + square((dy - ey)) + square((dz - ez)))
                * ((az - ez) * ((bx - ex) * (cy - ey) - (cx - ex) * (by - ey))
                    - (bz - ez) * ((ax - ex) * (cy - ey) - (cx - ex) * (ay - ey))
                    + (cz - ez) * ((ax - ex) * (by - ey) - (bx - ex) * (ay - ey)))
                - (square((cx - ex)) + square((cy - ey)) + square((cz - ez)))
                    * ((dz - ez) * ((ax - ex) * (by - ey) - (bx - ex) * (ay - ey))
                        + (az - ez) * ((bx - ex) * (dy - ey) - (dx - ex) * (by - ey))
                        + (bz - ez) * ((dx - ex) * (ay - ey) - (ax - ex) * (dy - ey)))
                + (square((bx - ex)) + square((by - ey)) + square((bz - ez)))
                    * ((cz - ez) * ((dx - ex) * (ay - ey) - (ax - ex) * (dy - ey))
                        + (dz - ez) * ((ax - ex) * (cy - ey) - (cx - ex) * (ay - ey))
                        + (az - ez) * ((cx - ex) * (dy - ey) - (dx - ex) * (cy - ey)))
                - (square((ax - ex)) + square((ay - ey)) + square((az - ez)))
                    * ((bz - ez) * ((cx - ex) * (dy - ey) - (dx - ex) * (cy - ey))
                        - (cz - ez) * ((bx - ex) * (dy - ey) - (dx - ex) * (by - ey))
                        + (dz - ez) * ((bx - ex) * (cy - ey) - (cx - ex) * (by - ey)))
        ) as i8)
    }

    /// Two [`orient3d`] signs.
    #[inline]
    pub fn plane_side(c: &[DVec3; 5]) -> i8 {
        super::plane_side_by(orient3d, c)
    }
}

/// Every peer's convention, checked: on ordinary (`uniform`) cases, where
/// every one of them is exact, each answers exactray's sign, so a peer
/// wrapped with the wrong sign fails here rather than as a report row of
/// wrong answers.
#[cfg(test)]
mod tests {
    use exactray::testing::{
        InputClass, SplitMix64, incircle_case, insphere_case, orient2d_case, orient3d_case,
        plane_side_case,
    };

    const CASES: usize = 2000;

    #[test]
    fn orient2d_conventions() {
        let mut rng = SplitMix64::new(1);
        for _ in 0..CASES {
            let p = orient2d_case(InputClass::Uniform, &mut rng);
            let want = exactray::predicates::orient2d(p[0], p[1], p[2]).as_i8();
            for f in [
                super::robust::orient2d,
                super::robust_drop_in::orient2d,
                super::arithmetica::orient2d,
                super::axiolid::orient2d,
                super::apfp::orient2d,
            ] {
                assert_eq!(f(&p), want, "{p:?}");
            }
        }
    }

    #[test]
    fn orient3d_conventions() {
        let mut rng = SplitMix64::new(2);
        for _ in 0..CASES {
            let [a, b, c, d] = orient3d_case(InputClass::Uniform, &mut rng);
            let want = exactray::predicates::orient3d(a, b, c, d).as_i8();
            for f in [
                super::robust::orient3d,
                super::robust_drop_in::orient3d,
                super::arithmetica::orient3d,
                super::axiolid::orient3d,
                super::apfp::orient3d,
            ] {
                assert_eq!(f(a, b, c, d), want, "{:?}", [a, b, c, d]);
            }
        }
    }

    #[test]
    fn incircle_conventions() {
        let mut rng = SplitMix64::new(3);
        for _ in 0..CASES {
            let p = incircle_case(InputClass::Uniform, &mut rng);
            let want = exactray::predicates::incircle(p[0], p[1], p[2], p[3]).as_i8();
            for f in [
                super::robust::incircle,
                super::robust_drop_in::incircle,
                super::arithmetica::incircle,
                super::axiolid::incircle,
                super::apfp::incircle,
            ] {
                assert_eq!(f(&p), want, "{p:?}");
            }
        }
    }

    #[test]
    fn insphere_and_plane_side_conventions() {
        let mut rng = SplitMix64::new(4);
        for _ in 0..CASES {
            let p = insphere_case(InputClass::Uniform, &mut rng);
            let want = exactray::predicates::insphere(p[0], p[1], p[2], p[3], p[4]).as_i8();
            for f in [
                super::robust::insphere,
                super::robust_drop_in::insphere,
                super::arithmetica::insphere,
                super::axiolid::insphere,
                super::apfp::insphere,
            ] {
                assert_eq!(f(&p), want, "{p:?}");
            }
            let q = plane_side_case(InputClass::Uniform, &mut rng);
            let want = exactray::predicates::same_side(q[0], q[1], q[2], q[3], q[4]).as_i8();
            for f in [
                super::robust::plane_side,
                super::robust_drop_in::plane_side,
                super::arithmetica::plane_side,
                super::axiolid::plane_side,
                super::apfp::plane_side,
            ] {
                assert_eq!(f(&q), want, "{q:?}");
            }
        }
    }
}
