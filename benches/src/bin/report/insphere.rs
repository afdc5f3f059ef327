//! insphere: positive when `e` is inside the sphere through `a, b, c, d`
//! with `orient3d(a, b, c, d) > 0` (CGAL's convention, minus Shewchuk's,
//! so the Shewchuk ports are negated).

use crate::framework::method;
use crate::signs::SignFamily;
use exactray::testing::insphere_case;
use exactray_oracle::oracle;
use exactray_peers::signs::{
    apfp, arithmetica, axiolid, minus_sign_of, naive, robust, robust_drop_in,
};
use glam::DVec3;

type Case = [DVec3; 5];

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
            method("naive", naive::insphere),
            method("robust", robust::insphere),
            method("robust-drop-in", robust_drop_in::insphere),
            method("geometry-predicates", |p: &Case| {
                let [a, b, c, d, e] = p.map(<[f64; 3]>::from);
                minus_sign_of(geometry_predicates::insphere(a, b, c, d, e))
            }),
            method("arithmetica", arithmetica::insphere),
            method("axiolid-predicates", axiolid::insphere),
            method("apfp", apfp::insphere),
        ],
    }
}
