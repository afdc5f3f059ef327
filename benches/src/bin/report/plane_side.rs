//! plane_side: whether `p` and `q` lie on the same side of the plane of
//! `x0, x1, x2` (1), on opposite sides (-1), or either on it (0). Peers
//! answer it with two orient3d calls, as a user of them would.

use crate::framework::method;
use crate::orient3d;
use crate::signs::SignFamily;
use exactray::testing::plane_side_case;
use exactray_oracle::oracle;
use exactray_peers::signs::{apfp, arithmetica, axiolid, naive, plane_side_by, robust};
use glam::DVec3;

type Case = [DVec3; 5];

pub fn family() -> SignFamily<Case> {
    SignFamily {
        name: "plane_side",
        generate: plane_side_case,
        oracle: |c| {
            let [x0, x1, x2, p, q] = c.map(<[f64; 3]>::from);
            oracle::plane_side(x0, x1, x2, p, q)
        },
        methods: vec![
            method("exactray", |&[x0, x1, x2, p, q]: &Case| {
                exactray::predicates::same_side(x0, x1, x2, p, q).as_i8()
            }),
            method("naive", naive::plane_side),
            method("robust", robust::plane_side),
            method("geometry-predicates", |c: &Case| {
                plane_side_by(orient3d::geometry_predicates, c)
            }),
            method("arithmetica", arithmetica::plane_side),
            method("axiolid-predicates", axiolid::plane_side),
            method("apfp", apfp::plane_side),
        ],
    }
}
