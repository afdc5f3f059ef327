//! orient2d: interim implementation (being replaced by the stage ladder).
use crate::sign::Sign;
use glam::DVec2;

pub(super) fn orient2d(a: DVec2, b: DVec2, c: DVec2) -> Sign {
    let p = |v: DVec2| robust::Coord { x: v.x, y: v.y };
    Sign::of_f64(robust::orient2d(p(a), p(b), p(c)))
}
