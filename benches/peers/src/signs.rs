//! The predicates' signs as exactray reports them (`Sign::as_i8`: `1`,
//! `0`, `-1`), computed by the textbook `f64` formulas and by the `robust`
//! crate (Shewchuk's adaptive predicates, negated where their convention
//! is the opposite of exactray's), with NaN as [`NAN`].

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
    match sign_of(v) {
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

/// The `robust` crate's predicates, in exactray's conventions.
pub mod robust {
    use super::{minus_sign_of, sign_of};
    use glam::{DVec2, DVec3};

    /// A point for the `robust` crate.
    #[inline]
    pub fn coord(p: DVec2) -> ::robust::Coord<f64> {
        ::robust::Coord { x: p.x, y: p.y }
    }

    /// A 3D point for the `robust` crate.
    #[inline]
    pub fn coord3(p: DVec3) -> ::robust::Coord3D<f64> {
        ::robust::Coord3D {
            x: p.x,
            y: p.y,
            z: p.z,
        }
    }

    /// `robust::orient2d`.
    #[inline]
    pub fn orient2d(&[a, b, c]: &[DVec2; 3]) -> i8 {
        sign_of(::robust::orient2d(coord(a), coord(b), coord(c)))
    }

    /// `robust::orient3d`, negated (Shewchuk's convention is minus CGAL's).
    #[inline]
    pub fn orient3d(a: DVec3, b: DVec3, c: DVec3, d: DVec3) -> i8 {
        minus_sign_of(::robust::orient3d(
            coord3(a),
            coord3(b),
            coord3(c),
            coord3(d),
        ))
    }

    /// `robust::incircle`.
    #[inline]
    pub fn incircle(&[a, b, c, d]: &[DVec2; 4]) -> i8 {
        sign_of(::robust::incircle(coord(a), coord(b), coord(c), coord(d)))
    }

    /// `robust::insphere`, negated.
    #[inline]
    pub fn insphere(p: &[DVec3; 5]) -> i8 {
        let [a, b, c, d, e] = p.map(coord3);
        minus_sign_of(::robust::insphere(a, b, c, d, e))
    }

    /// Two [`orient3d`] signs.
    #[inline]
    pub fn plane_side(c: &[DVec3; 5]) -> i8 {
        super::plane_side_by(orient3d, c)
    }
}
