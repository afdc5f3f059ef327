//! orient3d: the sign of `det[b - a, c - a, d - a]` (CGAL's convention,
//! minus Shewchuk's, so the Shewchuk ports are negated).

use crate::framework::method;
use crate::signs::{SignFamily, batch, coord3, minus_sign_of, sign_of};
use exactray::testing::orient3d_case;
use exactray_oracle::oracle;
use glam::DVec3;

type Case = [DVec3; 4];

pub fn naive(a: DVec3, b: DVec3, c: DVec3, d: DVec3) -> i8 {
    sign_of((b - a).dot((c - a).cross(d - a)))
}

pub fn robust(a: DVec3, b: DVec3, c: DVec3, d: DVec3) -> i8 {
    minus_sign_of(robust::orient3d(coord3(a), coord3(b), coord3(c), coord3(d)))
}

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
            method("naive", |&[a, b, c, d]: &Case| naive(a, b, c, d)),
            method("robust", |&[a, b, c, d]: &Case| robust(a, b, c, d)),
            method("geometry-predicates", |&[a, b, c, d]: &Case| {
                geometry_predicates(a, b, c, d)
            }),
        ],
    }
}
