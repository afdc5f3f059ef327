//! The `mint` feature: mint's points and vectors are accepted wherever
//! glam's are, converted exactly (`f32` widened), with the same answers.
#![cfg(feature = "mint")]

use exactray::prelude::*;
use exactray::{IntoDVec2, IntoDVec3};
use glam::{DVec2, DVec3};
use mint::{Point2, Point3, Vector2, Vector3};

#[test]
fn conversions_are_exact() {
    let tiny = f64::from_bits(1);
    assert_eq!(
        Point2 {
            x: tiny,
            y: -f64::MAX
        }
        .into_dvec2(),
        DVec2::new(tiny, -f64::MAX)
    );
    assert_eq!(
        Vector2 { x: 0.1, y: 0.2 }.into_dvec2(),
        DVec2::new(0.1, 0.2)
    );
    assert_eq!(
        Point3 {
            x: 0.1,
            y: tiny,
            z: f64::MAX
        }
        .into_dvec3(),
        DVec3::new(0.1, tiny, f64::MAX)
    );
    assert_eq!(
        Vector3 {
            x: 1.0,
            y: 2.0,
            z: 3.0
        }
        .into_dvec3(),
        DVec3::new(1.0, 2.0, 3.0)
    );
    // f32 widens without rounding.
    let third = 1.0f32 / 3.0;
    assert_eq!(
        Point2 {
            x: third,
            y: 0.0f32
        }
        .into_dvec2()
        .x,
        f64::from(third)
    );
    assert_eq!(
        Vector3 {
            x: 0.0,
            y: 0.0,
            z: third
        }
        .into_dvec3()
        .z,
        f64::from(third)
    );
}

#[test]
fn predicates_and_shapes_take_mint_points() {
    let p2 = |x: f64, y: f64| Point2 { x, y };
    let p3 = |x: f64, y: f64, z: f64| Point3 { x, y, z };
    // Collinear only in exact arithmetic on the doubles 0.1, 0.2, 0.3.
    assert_eq!(
        orient2d(p2(0.1, 0.1), p2(0.2, 0.2), p2(0.3, 0.3)),
        Sign::Zero
    );
    assert_eq!(
        orient2d(p2(0.0, 0.0), p2(1e-200, 0.0), p2(0.0, 1e-200)),
        Sign::Positive
    );
    assert_eq!(
        orient3d(
            p3(0.0, 0.0, 0.0),
            p3(1.0, 0.0, 0.0),
            p3(0.0, 1.0, 0.0),
            p3(0.0, 0.0, 1e-300)
        ),
        Sign::Positive
    );
    let ray = Ray::new(
        p3(0.25, 0.25, 1.0),
        Vector3 {
            x: 0.0,
            y: 0.0,
            z: -1.0,
        },
    )
    .unwrap();
    let tri = Triangle::new(p3(0.0, 0.0, 0.0), p3(1.0, 0.0, 0.0), p3(0.0, 1.0, 0.0)).unwrap();
    assert_eq!(tri.cast_exact(&ray, Interval::FORWARD).unwrap().t, 1.0);
    // Bad input is the same typed error.
    assert_eq!(
        try_orient2d(p2(f64::NAN, 0.0), p2(1.0, 0.0), p2(0.0, 1.0)),
        Err(InputError::NonFinite { argument: "a" })
    );
}
