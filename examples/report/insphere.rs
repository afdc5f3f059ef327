//! insphere: positive when `e` is inside the sphere through `a, b, c, d`
//! with `orient3d(a, b, c, d) > 0` (CGAL's convention, minus Shewchuk's,
//! so the Shewchuk ports are negated).

use crate::framework::method;
use crate::signs::{SignFamily, coord3, minus_sign_of};
use exactray::testing::insphere_case;
use exactray_oracle::oracle;
use glam::DVec3;

type Case = [DVec3; 5];

/// Shewchuk's `inspherefast`, negated.
fn naive(&[a, b, c, d, e]: &Case) -> i8 {
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

pub fn family() -> SignFamily<Case> {
    SignFamily {
        name: "insphere",
        generate: insphere_case,
        oracle: |p| {
            let [a, b, c, d, e] = p.map(<[f64; 3]>::from);
            oracle::insphere(a, b, c, d, e)
        },
        methods: vec![
            method("exactray", |&[a, b, c, d, e]: &Case| {
                exactray::predicates::insphere(a, b, c, d, e).as_i8()
            }),
            method("naive", naive),
            method("robust", |p: &Case| {
                let [a, b, c, d, e] = p.map(coord3);
                minus_sign_of(robust::insphere(a, b, c, d, e))
            }),
            method("geometry-predicates", |p: &Case| {
                let [a, b, c, d, e] = p.map(<[f64; 3]>::from);
                minus_sign_of(geometry_predicates::insphere(a, b, c, d, e))
            }),
        ],
    }
}
