//! The `serde` feature: every plain data type survives a round trip to
//! the bit, and data that a validating constructor rejects is a
//! deserialization error naming the [`InputError`], never an invalid value.
//! JSON (with exact float parsing) for data written by hand, CBOR for
//! values JSON cannot hold (infinities, NaN).
#![cfg(feature = "serde")]

use exactray::bvh::Nearest;
use exactray::interval::Interval;
use exactray::predicates::SideRelation;
use exactray::query::ray::{Hit, Ray, RayCast, TriangleHit};
use exactray::roots::{BoundedRoot, Roots};
use exactray::scene::{AnalyticShape, PrimitiveId, SceneBuilder, TriangleMesh};
use exactray::shape::{
    Aabb, CappedCylinder, Cone, Cylinder, Disk, Plane, Quadric, Sphere, Triangle,
};
use exactray::{InputError, Sign};
use glam::DVec3;
use serde::Serialize;
use serde::de::DeserializeOwned;
use std::fmt::Debug;

fn json<T: Serialize + DeserializeOwned>(v: &T) -> T {
    serde_json::from_str(&serde_json::to_string(v).expect("serializes")).expect("deserializes")
}

fn cbor<T: Serialize + DeserializeOwned>(v: &T) -> T {
    let mut bytes = Vec::new();
    ciborium::into_writer(v, &mut bytes).expect("serializes");
    ciborium::from_reader(&bytes[..]).expect("deserializes")
}

/// A round trip through both formats gives back an equal value.
fn round_trip<T: Serialize + DeserializeOwned + PartialEq + Debug>(v: T) {
    assert_eq!(json(&v), v, "JSON: {}", serde_json::to_string(&v).unwrap());
    assert_eq!(cbor(&v), v, "CBOR");
}

/// The error a JSON text gives as a `T`.
fn json_error<T: DeserializeOwned + Debug>(text: &str) -> String {
    serde_json::from_str::<T>(text).expect_err(text).to_string()
}

/// Awkward coordinates: a subnormal, the largest finite, a value that
/// needs all 17 digits.
fn awkward() -> DVec3 {
    DVec3::new(f64::from_bits(1), -f64::MAX, 0.1 + 0.2)
}

#[test]
fn shapes_round_trip_to_the_bit() {
    let p = awkward();
    round_trip(Sphere::new(p, 1e-300).unwrap());
    round_trip(Cylinder::new(p, [0.0, 1e300, 3.0], 2.5).unwrap());
    round_trip(CappedCylinder::new(p, [1.0, 0.0, 0.0], 0.75).unwrap());
    round_trip(Cone::new(p, [0.0, 0.0, 2.0], 1.0).unwrap());
    round_trip(Cone::infinite(p, [0.0, 0.0, 2.0], 1.0).unwrap());
    round_trip(Plane::new(p, [0.0, 0.0, -1.0]).unwrap());
    round_trip(Disk::new(p, [0.0, 1.0, 0.0], 0.5).unwrap());
    round_trip(Quadric::new([1.0, 1.0, -1.0, 0.0, 0.1, 0.0, 0.0, 0.0, 2.0, -3.0]).unwrap());
    round_trip(Triangle::new(p, [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]).unwrap());
    round_trip(Aabb::new([-1.0, -2.0, -3.0], p.abs()).unwrap());
    // Infinite bounds: CBOR holds them (JSON writes null).
    let whole = Aabb::new(DVec3::NEG_INFINITY, DVec3::INFINITY).unwrap();
    assert_eq!(cbor(&whole), whole);
}

#[test]
fn rays_intervals_and_signs_round_trip() {
    round_trip(Ray::new(awkward(), [0.0, 0.0, -1e-320]).unwrap());
    round_trip(Interval::new(-0.0, 1e308).unwrap());
    assert_eq!(cbor(&Interval::FORWARD), Interval::FORWARD);
    for s in [Sign::Negative, Sign::Zero, Sign::Positive] {
        round_trip(s);
    }
    for s in [
        SideRelation::Same,
        SideRelation::Opposite,
        SideRelation::OnPlane,
    ] {
        round_trip(s);
    }
    for r in [
        Roots::None,
        Roots::One(0.5),
        Roots::Two(-1.0, 3.0),
        Roots::All,
    ] {
        round_trip(r);
    }
    round_trip(BoundedRoot {
        t: 2.0,
        error: 1e-15,
    });
    round_trip(Nearest {
        index: 7,
        point: awkward(),
        distance: 0.25,
    });
}

#[test]
fn hits_round_trip() {
    let sphere = Sphere::new([0.0, 0.0, 0.0], 1.0).unwrap();
    let ray = Ray::new([-5.0, 0.1, 0.0], [1.0, 0.0, 0.0]).unwrap();
    let hit: Hit = sphere.cast(&ray, Interval::FORWARD).unwrap();
    round_trip(hit);
    let tri = Triangle::new([0.0, 0.0, 0.0], [4.0, 0.0, 0.0], [0.0, 4.0, 0.0]).unwrap();
    let down = Ray::new([1.0, 2.0, 5.0], [0.0, 0.0, -1.0]).unwrap();
    let th: TriangleHit = tri.cast_exact(&down, Interval::FORWARD).unwrap();
    round_trip(th);

    let mesh = TriangleMesh::new(
        &[[0.0, 0.0, 0.0], [4.0, 0.0, 0.0], [0.0, 4.0, 0.0]],
        &[[0, 1, 2]],
    )
    .unwrap();
    round_trip(mesh.closest_hit(&down, Interval::FORWARD).unwrap());
    let mut builder = SceneBuilder::new();
    builder.add(sphere).unwrap();
    builder.add(mesh).unwrap();
    let scene = builder.build();
    let scene_hit = scene.closest_hit(&down, Interval::FORWARD).unwrap();
    round_trip(scene_hit);
    round_trip(PrimitiveId(3));
    round_trip(AnalyticShape::from(sphere));
    round_trip(AnalyticShape::from(
        Cone::infinite([0.0; 3], [0.0, 0.0, 1.0], 2.0).unwrap(),
    ));
}

#[test]
fn meshes_round_trip_and_rebuild_their_hierarchy() {
    let vertices = [
        [0.0, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [0.0, 1.0, 0.0],
        [1.0, 1.0, 1e-300],
    ];
    let triangles = [[0, 1, 2], [1, 3, 2]];
    let mesh = TriangleMesh::new(&vertices, &triangles)
        .unwrap()
        .with_normals(&[[0.0, 0.0, 1.0]; 4])
        .unwrap();
    for back in [json(&mesh), cbor(&mesh)] {
        assert_eq!(back.vertices(), mesh.vertices());
        assert_eq!(back.triangles(), mesh.triangles());
        assert_eq!(back.normals(), mesh.normals());
        let ray = Ray::new([0.7, 0.7, 1.0], [0.0, 0.0, -1.0]).unwrap();
        assert_eq!(
            back.closest_hit(&ray, Interval::FORWARD),
            mesh.closest_hit(&ray, Interval::FORWARD)
        );
    }
    // Normals may be left out.
    let plain: TriangleMesh =
        serde_json::from_str(r#"{"vertices": [[0,0,0],[1,0,0],[0,1,0]], "triangles": [[0,1,2]]}"#)
            .unwrap();
    assert_eq!(plain.normals(), None);
}

/// What each constructor rejects, the deserializer rejects with the same
/// [`InputError`]'s message.
#[test]
fn invalid_data_is_an_error_naming_the_constructors_reason() {
    let reason = |e: InputError| e.to_string();
    let cases: [(String, String); 10] = [
        (
            json_error::<Sphere>(r#"{"center": [0, 0, 0], "radius": -1}"#),
            reason(InputError::InvalidRadius { argument: "radius" }),
        ),
        (
            json_error::<Ray>(r#"{"origin": [0, 0, 0], "direction": [0, 0, 0]}"#),
            reason(InputError::ZeroDirection),
        ),
        (
            json_error::<Interval>(r#"{"min": 2, "max": 1}"#),
            reason(InputError::ReversedInterval),
        ),
        (
            json_error::<Cylinder>(r#"{"point": [0, 0, 0], "axis": [0, 0, 0], "radius": 1}"#),
            reason(InputError::Degenerate { argument: "axis" }),
        ),
        (
            json_error::<Cone>(
                r#"{"apex": [0, 0, 0], "axis": [0, 0, 1], "radius": 0, "capped": true}"#,
            ),
            reason(InputError::Degenerate { argument: "radius" }),
        ),
        (
            json_error::<Plane>(r#"{"point": [0, 0, 0], "normal": [0, 0, 0]}"#),
            reason(InputError::Degenerate { argument: "normal" }),
        ),
        (
            json_error::<Disk>(r#"{"center": [0, 0, 0], "normal": [0, 0, 1], "radius": -0.5}"#),
            reason(InputError::InvalidRadius { argument: "radius" }),
        ),
        (
            json_error::<Aabb>(r#"{"min": [1, 0, 0], "max": [0, 0, 0]}"#),
            reason(InputError::ReversedInterval),
        ),
        (
            json_error::<TriangleMesh>(
                r#"{"vertices": [[0,0,0],[1,0,0],[0,1,0]], "triangles": [[0,1,3]]}"#,
            ),
            reason(InputError::IndexOutOfRange { index: 3, len: 3 }),
        ),
        (
            json_error::<TriangleMesh>(
                r#"{"vertices": [[0,0,0],[1,0,0],[0,1,0]], "triangles": [[0,1,2]], "normals": [[0,0,1]]}"#,
            ),
            reason(InputError::LengthMismatch {
                expected: 3,
                got: 1,
            }),
        ),
    ];
    for (got, want) in cases {
        assert!(got.contains(&want), "{got:?} does not carry {want:?}");
    }
    // Unknown and missing fields are errors too, not defaults.
    assert!(
        json_error::<Sphere>(r#"{"center": [0, 0, 0], "radius": 1, "colour": 2}"#)
            .contains("unknown field")
    );
    assert!(json_error::<Ray>(r#"{"origin": [0, 0, 0]}"#).contains("missing field"));
}

/// Non-finite coordinates, which JSON cannot write, through CBOR.
#[test]
fn non_finite_coordinates_are_rejected() {
    #[derive(Serialize)]
    struct SphereData {
        center: [f64; 3],
        radius: f64,
    }
    #[derive(Serialize)]
    struct RayData {
        origin: [f64; 3],
        direction: [f64; 3],
    }
    #[derive(Serialize)]
    struct TriangleData {
        vertices: [[f64; 3]; 3],
    }
    #[derive(Serialize)]
    struct QuadricData {
        coefficients: [f64; 10],
    }
    fn cbor_error<T: DeserializeOwned + Debug>(v: &impl Serialize) -> String {
        let mut bytes = Vec::new();
        ciborium::into_writer(v, &mut bytes).unwrap();
        ciborium::from_reader::<T, _>(&bytes[..])
            .unwrap_err()
            .to_string()
    }
    let non_finite = |argument| InputError::NonFinite { argument }.to_string();
    let e = cbor_error::<Sphere>(&SphereData {
        center: [f64::NAN, 0.0, 0.0],
        radius: 1.0,
    });
    assert!(e.contains(&non_finite("center")), "{e}");
    let e = cbor_error::<Sphere>(&SphereData {
        center: [0.0; 3],
        radius: f64::NAN,
    });
    assert!(
        e.contains(&InputError::InvalidRadius { argument: "radius" }.to_string()),
        "{e}"
    );
    let e = cbor_error::<Ray>(&RayData {
        origin: [0.0, f64::INFINITY, 0.0],
        direction: [1.0, 0.0, 0.0],
    });
    assert!(e.contains(&non_finite("origin")), "{e}");
    let e = cbor_error::<Triangle>(&TriangleData {
        vertices: [[0.0; 3], [1.0, 0.0, 0.0], [0.0, f64::NEG_INFINITY, 0.0]],
    });
    assert!(e.contains(&non_finite("v2")), "{e}");
    let mut k = [0.0; 10];
    k[4] = f64::NAN;
    let e = cbor_error::<Quadric>(&QuadricData { coefficients: k });
    assert!(e.contains(&non_finite("coefficients")), "{e}");
}
