//! orient2d: the sign of `(b - a) x (c - a)`, positive counterclockwise.

use crate::framework::method;
use crate::signs::{SignFamily, batch};
use exactray::testing::orient2d_case;
use exactray_oracle::oracle;
use exactray_peers::signs::{apfp, arithmetica, axiolid, naive, robust, robust_drop_in, sign_of};
use glam::DVec2;

type Case = [DVec2; 3];

pub fn family() -> SignFamily<Case> {
    SignFamily {
        name: "orient2d",
        generate: orient2d_case,
        oracle: |&[a, b, c]| oracle::orient2d(a.into(), b.into(), c.into()),
        methods: vec![
            method("exactray", |&[a, b, c]: &Case| {
                exactray::predicates::orient2d(a, b, c).as_i8()
            }),
            batch("exactray-batch", exactray::predicates::orient2d_many),
            method("naive", naive::orient2d),
            method("robust", robust::orient2d),
            method("robust-drop-in", robust_drop_in::orient2d),
            method("geometry-predicates", |&[a, b, c]: &Case| {
                sign_of(geometry_predicates::orient2d(a.into(), b.into(), c.into()))
            }),
            method("arithmetica", arithmetica::orient2d),
            method("axiolid-predicates", axiolid::orient2d),
            method("apfp", apfp::orient2d),
        ],
    }
}
