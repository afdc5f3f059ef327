//! orient3d: the sign of `det[b - a, c - a, d - a]` (CGAL's convention,
//! minus Shewchuk's, so the Shewchuk ports are negated).

use crate::framework::method;
use crate::signs::{SignFamily, batch};
use exactray::testing::orient3d_case;
use exactray_oracle::oracle;
use exactray_peers::signs::{
    apfp, arithmetica, axiolid, minus_sign_of, naive, robust, robust_drop_in,
};
use glam::DVec3;

type Case = [DVec3; 4];

pub fn geometry_predicates(a: DVec3, b: DVec3, c: DVec3, d: DVec3) -> i8 {
    let [a, b, c, d] = [a, b, c, d].map(<[f64; 3]>::from);
    minus_sign_of(geometry_predicates::orient3d(a, b, c, d))
}

pub fn family() -> SignFamily<Case> {
    SignFamily {
        name: "orient3d",
        generate: orient3d_case,
        oracle: |&[a, b, c, d]| oracle::orient3d(a.into(), b.into(), c.into(), d.into()),
        methods: vec![
            method("exactray", |&[a, b, c, d]: &Case| {
                exactray::predicates::orient3d(a, b, c, d).as_i8()
            }),
            batch("exactray-batch", exactray::predicates::orient3d_many),
            method("naive", |&[a, b, c, d]: &Case| naive::orient3d(a, b, c, d)),
            method("robust", |&[a, b, c, d]: &Case| {
                robust::orient3d(a, b, c, d)
            }),
            method("robust-drop-in", |&[a, b, c, d]: &Case| {
                robust_drop_in::orient3d(a, b, c, d)
            }),
            method("geometry-predicates", |&[a, b, c, d]: &Case| {
                geometry_predicates(a, b, c, d)
            }),
            method("arithmetica", |&[a, b, c, d]: &Case| {
                arithmetica::orient3d(a, b, c, d)
            }),
            method("axiolid-predicates", |&[a, b, c, d]: &Case| {
                axiolid::orient3d(a, b, c, d)
            }),
            method("apfp", |&[a, b, c, d]: &Case| apfp::orient3d(a, b, c, d)),
        ],
    }
}
