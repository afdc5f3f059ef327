//! incircle: positive when `d` is inside the circle through counterclockwise
//! `a, b, c` (the same convention as Shewchuk's).

use crate::framework::method;
use crate::signs::{SignFamily, coord, sign_of};
use exactray::testing::incircle_case;
use exactray_oracle::oracle;
use glam::DVec2;

type Case = [DVec2; 4];

/// Shewchuk's `incirclefast`, expanded along the lifted column.
fn naive(&[a, b, c, d]: &Case) -> i8 {
    let (ad, bd, cd) = (a - d, b - d, c - d);
    let det = ad.length_squared() * bd.perp_dot(cd)
        + bd.length_squared() * cd.perp_dot(ad)
        + cd.length_squared() * ad.perp_dot(bd);
    sign_of(det)
}

pub fn family() -> SignFamily<Case> {
    SignFamily {
        name: "incircle",
        generate: incircle_case,
        oracle: |&[a, b, c, d]| oracle::incircle(a.into(), b.into(), c.into(), d.into()),
        methods: vec![
            method("exactray", |&[a, b, c, d]: &Case| {
                exactray::predicates::incircle(a, b, c, d).as_i8()
            }),
            method("naive", naive),
            method("robust", |&[a, b, c, d]: &Case| {
                sign_of(robust::incircle(coord(a), coord(b), coord(c), coord(d)))
            }),
            method("geometry-predicates", |p: &Case| {
                sign_of(geometry_predicates::incircle(
                    p[0].into(),
                    p[1].into(),
                    p[2].into(),
                    p[3].into(),
                ))
            }),
        ],
    }
}
