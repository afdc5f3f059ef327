//! incircle: positive when `d` is inside the circle through counterclockwise
//! `a, b, c` (the same convention as Shewchuk's).

use crate::framework::method;
use crate::signs::SignFamily;
use exactray::testing::incircle_case;
use exactray_oracle::oracle;
use exactray_peers::signs::{apfp, arithmetica, axiolid, naive, robust, robust_drop_in, sign_of};
use glam::DVec2;

type Case = [DVec2; 4];

pub fn family() -> SignFamily<Case> {
    SignFamily {
        name: "incircle",
        generate: incircle_case,
        oracle: |&[a, b, c, d]| oracle::incircle(a.into(), b.into(), c.into(), d.into()),
        methods: vec![
            method("exactray", |&[a, b, c, d]: &Case| {
                exactray::predicates::incircle(a, b, c, d).as_i8()
            }),
            method("naive", naive::incircle),
            method("robust", robust::incircle),
            method("robust-drop-in", robust_drop_in::incircle),
            method("geometry-predicates", |p: &Case| {
                sign_of(geometry_predicates::incircle(
                    p[0].into(),
                    p[1].into(),
                    p[2].into(),
                    p[3].into(),
                ))
            }),
            method("arithmetica", arithmetica::incircle),
            method("axiolid-predicates", axiolid::incircle),
            method("apfp", apfp::incircle),
        ],
    }
}
