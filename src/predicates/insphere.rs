//! insphere: interim implementation (being replaced by the stage ladder).
use crate::sign::Sign;
use glam::DVec3;

pub(super) fn insphere(a: DVec3, b: DVec3, c: DVec3, d: DVec3, e: DVec3) -> Sign {
    let p = |v: DVec3| robust::Coord3D { x: v.x, y: v.y, z: v.z };
    -Sign::of_f64(robust::insphere(p(a), p(b), p(c), p(d), p(e)))
}
