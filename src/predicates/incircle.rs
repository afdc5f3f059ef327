//! incircle: interim implementation (being replaced by the stage ladder).
use crate::sign::Sign;
use glam::DVec2;

pub(super) fn incircle(a: DVec2, b: DVec2, c: DVec2, d: DVec2) -> Sign {
    let p = |v: DVec2| robust::Coord { x: v.x, y: v.y };
    Sign::of_f64(robust::incircle(p(a), p(b), p(c), p(d)))
}
