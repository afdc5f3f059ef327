//! The performance targets the crate promises, checked on the rows of this
//! run: a ratio is only fair between times measured side by side.

use crate::framework::Row;
use crate::output::{markdown, ratio_to};

/// `exactray` on `family`/`inputs` takes at most `max_ratio` times the
/// `against` method's time, and with `exact` also answers every case right.
/// An empty `against` sets no time target: only `exact`.
struct Target {
    family: &'static str,
    /// The row under test: `exactray` unless a family's target names a
    /// variant (`exactray-exact`, ...).
    method: &'static str,
    inputs: &'static str,
    against: &'static str,
    max_ratio: f64,
    exact: bool,
}

fn targets(rows: &[Row]) -> Vec<Target> {
    let t = |family, inputs, against, max_ratio, exact| Target {
        family,
        method: "exactray",
        inputs,
        against,
        max_ratio,
        exact,
    };
    let mut all = vec![
        t("orient2d", "uniform", "naive", 1.5, false),
        t("orient3d", "uniform", "naive", 1.5, false),
        t("orient3d", "near-degenerate", "robust", 0.5, false),
        t("orient3d", "degenerate", "robust", 0.5, false),
        t("orient2d", "near-degenerate", "robust", 1.0, false),
        t("orient2d", "degenerate", "robust", 1.0, false),
    ];
    for family in ["orient2d", "orient3d", "incircle", "insphere", "plane_side"] {
        for inputs in ["tiny", "huge", "mixed"] {
            all.push(t(family, inputs, "robust", 1.0, true));
        }
    }
    // Nearest points at 10^6 points: at least as fast as kiddo in
    // distribution and as rstar off it, 3x faster than rstar in
    // distribution, built at least as fast as kiddo; never a wrong point.
    all.extend([
        t("nearest", "uniform:1000000", "kiddo", 1.0, false),
        t("nearest", "clustered:1000000", "kiddo", 1.0, false),
        t("nearest", "off-distribution:1000000", "rstar", 1.0, false),
        t("nearest", "uniform:1000000", "rstar", 1.0 / 3.0, false),
        t("nearest", "clustered:1000000", "rstar", 1.0 / 3.0, false),
        t("nearest_build", "uniform:1000000", "kiddo", 1.0, false),
        t("nearest_build", "clustered:1000000", "kiddo", 1.0, false),
    ]);
    for inputs in [
        "uniform:10000",
        "uniform:100000",
        "uniform:1000000",
        "clustered:10000",
        "clustered:100000",
        "clustered:1000000",
        "off-distribution:10000",
        "off-distribution:100000",
        "off-distribution:1000000",
    ] {
        all.push(t("nearest", inputs, "", 0.0, true));
    }
    // Ray–triangle: the watertight variant within 1.3x of
    // Möller–Trumbore and the exact one within 2x on ordinary rays; parry3d
    // at least 1.5x slower than the watertight one (at most 1/1.5 of its
    // time); no false miss at shared edges for either, no wrong hit or miss
    // for the exact one.
    let variant = |method, inputs, against, max_ratio, exact| Target {
        method,
        ..t("ray_triangle", inputs, against, max_ratio, exact)
    };
    all.extend([
        variant("exactray-watertight", "uniform", "exactray-mt", 1.3, false),
        variant("exactray-exact", "uniform", "exactray-mt", 2.0, true),
        variant(
            "exactray-watertight",
            "uniform",
            "parry3d",
            1.0 / 1.5,
            false,
        ),
        variant("exactray-watertight", "shared-edges", "", 0.0, true),
        variant("exactray-exact", "shared-edges", "", 0.0, true),
    ]);
    for inputs in ["far", "near-edge", "grazing"] {
        all.push(variant("exactray-exact", inputs, "", 0.0, true));
    }
    // The prepared exact ray–triangle test at most 2x Möller–Trumbore on ordinary
    // rays with the ray prepared once (as a scene does), in either tier
    // (`t` within 4 ulps, or with its certified bound); no wrong hit or
    // miss, and no exact `t` outside a returned bound, on any input.
    for method in ["exactray-exact-prepared", "exactray-exact-bounded"] {
        all.push(variant(method, "uniform", "exactray-mt", 2.0, true));
        for inputs in ["far", "near-edge", "grazing", "shared-edges"] {
            all.push(variant(method, inputs, "", 0.0, true));
        }
    }
    // Quadrics in tiers: the default cast (exact hit or miss,
    // the stable formula's root with a certified bound) at most 1.2x Ray
    // Tracing Gems' stable form and at most parry3d's time on `uniform`
    // and `far` rays; no wrong hit or miss and no exact root outside the
    // returned bound on any class, in either tier.
    for family in ["ray_sphere", "ray_cylinder", "ray_cone", "ray_quadric"] {
        for inputs in ["uniform", "far"] {
            all.push(t(family, inputs, "naive-stable", 1.2, true));
            if family != "ray_quadric" {
                all.push(t(family, inputs, "parry3d", 1.0, true));
            }
        }
    }
    let families: [(&str, &[&str]); 4] = [
        ("ray_sphere", &["grazing", "tangent"]),
        ("ray_cylinder", &["any-axis", "grazing", "parallel"]),
        ("ray_cone", &[]),
        ("ray_quadric", &["degenerate"]),
    ];
    for (family, classes) in families {
        for &inputs in classes {
            all.push(t(family, inputs, "", 0.0, true));
        }
        for inputs in ["uniform", "far"].iter().chain(classes) {
            all.push(Target {
                method: "exactray-precise",
                ..t(family, inputs, "", 0.0, true)
            });
        }
    }
    // Predicates on constructed points: no wrong sign or order on any
    // class; on uniform inputs at most 2x the explicit orient3d timed in
    // the same loops.
    const PREDICATES: [&str; 4] = [
        "orient3d_lpi",
        "orient3d_tpi",
        "orient2d_ssi",
        "less_on_axis_lpi",
    ];
    for pred in PREDICATES {
        for class in [
            "uniform",
            "near-degenerate",
            "degenerate",
            "tiny",
            "huge",
            "mixed",
        ] {
            let inputs = &*String::leak(format!("{pred}:{class}"));
            if class == "uniform" {
                all.push(t("implicit", inputs, "explicit-orient3d", 2.0, true));
            } else {
                all.push(t("implicit", inputs, "", 0.0, true));
            }
        }
    }
    all.extend(scene_targets(rows));
    all
}

/// Scenes (inputs named by their triangle counts, so read off the rows),
/// each against a peer only where the run measured it: the default
/// closest hit at most obvhs's `CwBvh` time and tinybvh's double-precision
/// BVH's on every input, a third of parry3d's and 1.5x Embree's on camera
/// and diffuse rays of the spheres and the room, the exact variant within
/// 1.3x of it; the rayon batch at least 1.8x faster than the one-core
/// batch; a shadow ray at most 1.5x Embree's and obvhs's time, and at
/// most 0.7x a closest-hit query's on the same rays where most are
/// blocked (`blocked-shadow`); no spawned ray that hits the surface it
/// leaves.
fn scene_targets(rows: &[Row]) -> Vec<Target> {
    let inputs_of = |family: &str, method: &str| -> Vec<&'static str> {
        rows.iter()
            .filter(|r| r.family == family && r.method == method)
            .map(|r| &*String::leak(r.inputs.clone()))
            .collect()
    };
    let measured = |family: &str, method: &str, inputs: &str| {
        rows.iter()
            .any(|r| r.family == family && r.method == method && r.inputs == inputs)
    };
    let mut all = Vec::new();
    let mut push = |family, method, inputs, against, max_ratio| {
        if measured(family, against, inputs) {
            all.push(Target {
                family,
                method,
                inputs,
                against,
                max_ratio,
                exact: false,
            });
        }
    };
    for inputs in inputs_of("closest_hit", "exactray") {
        push("closest_hit", "exactray", inputs, "obvhs", 1.0);
        push("closest_hit", "exactray", inputs, "tinybvh-f64", 1.0);
        push("closest_hit", "exactray-exact", inputs, "exactray", 1.3);
        push(
            "closest_hit",
            "exactray-rayon",
            inputs,
            "exactray-batch",
            1.0 / 1.8,
        );
        let camera_or_diffuse = inputs.contains("primary") || inputs.contains("diffuse");
        if camera_or_diffuse && !inputs.starts_with("terrain") {
            push("closest_hit", "exactray", inputs, "parry3d", 1.0 / 3.0);
            push("closest_hit", "exactray", inputs, "embree", 1.5);
        }
    }
    for inputs in inputs_of("any_hit", "exactray") {
        push("any_hit", "exactray", inputs, "embree", 1.5);
        push("any_hit", "exactray", inputs, "obvhs", 1.0);
        if inputs.starts_with("blocked-shadow") {
            push("any_hit", "exactray", inputs, "exactray-closest", 0.7);
        }
    }
    for inputs in inputs_of("spawn", "exactray") {
        all.push(Target {
            family: "spawn",
            method: "exactray",
            inputs,
            against: "",
            max_ratio: 0.0,
            exact: true,
        });
    }
    all
}

/// A markdown table of the targets whose rows this run measured, and how
/// many of them were met.
pub fn check(rows: &[Row]) -> (String, usize, usize) {
    let mut body = Vec::new();
    let mut met = 0;
    for t in targets(rows) {
        // The batch variants (`orient2d_many`, ...) are the crate's
        // documented way to evaluate many predicates: where a family has
        // them, the uniform-against-naive target counts the faster row.
        let batch_ok = t.inputs == "uniform" && t.against == "naive";
        let Some(row) = rows
            .iter()
            .filter(|r| r.family == t.family && r.inputs == t.inputs)
            .filter(|r| r.method == t.method || (batch_ok && r.method == "exactray-batch"))
            .min_by(|a, b| a.ns_per_op.total_cmp(&b.ns_per_op))
        else {
            continue;
        };
        let timed = !t.against.is_empty();
        let ratio = ratio_to(rows, row, t.against);
        let ok =
            (!timed || ratio.is_some_and(|v| v <= t.max_ratio)) && (!t.exact || row.errors == 0);
        met += ok as usize;
        let wrong = match (row.family, row.inputs.as_str()) {
            ("ray_triangle", "shared-edges") => "false miss",
            (f, _) if f.starts_with("ray_") && row.method.ends_with("bounded") => {
                "wrong hit, miss or bound"
            }
            (f, _) if f.starts_with("ray_") => "wrong hit or miss",
            (f, _) if f.starts_with("nearest") => "wrong point",
            ("spawn", _) => "self-intersection",
            _ => "wrong sign",
        };
        // One or two decimals: 1/3 shows as 0.33.
        let max = if (t.max_ratio * 10.0).fract() == 0.0 {
            format!("{:.1}", t.max_ratio)
        } else {
            format!("{:.2}", t.max_ratio)
        };
        let target = match (timed, t.exact) {
            (true, true) => format!("<= {max}x {}, no {wrong}", t.against),
            (true, false) => format!("<= {max}x {}", t.against),
            (false, _) => format!("no {wrong}"),
        };
        body.push(vec![
            match row.method.strip_prefix("exactray") {
                Some("") | None => format!("{}/{}", t.family, t.inputs),
                Some(how) => format!("{}/{} ({})", t.family, t.inputs, &how[1..]),
            },
            target,
            format!(
                "{}, {} wrong",
                ratio.map_or("-".to_string(), |v| format!("{v:.2}x")),
                row.errors
            ),
            if ok { "met" } else { "MISSED" }.to_string(),
        ]);
    }
    let total = body.len();
    (
        markdown(&["exactray on", "target", "measured", ""], &body),
        met,
        total,
    )
}
