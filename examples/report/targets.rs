//! The performance targets the crate promises, checked on the rows of this
//! run: a ratio is only fair between times measured side by side.

use crate::framework::Row;
use crate::output::{markdown, ratio_to};

/// `exactray` on `family`/`inputs` takes at most `max_ratio` times the
/// `against` method's time, and with `exact` also answers every case right.
struct Target {
    family: &'static str,
    inputs: &'static str,
    against: &'static str,
    max_ratio: f64,
    exact: bool,
}

fn targets() -> Vec<Target> {
    let t = |family, inputs, against, max_ratio, exact| Target {
        family,
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
    all
}

/// A markdown table of the targets whose rows this run measured, and how
/// many of them were met.
pub fn check(rows: &[Row]) -> (String, usize, usize) {
    let mut body = Vec::new();
    let mut met = 0;
    for t in targets() {
        let Some(row) = rows
            .iter()
            .find(|r| r.family == t.family && r.inputs == t.inputs && r.method == "exactray")
        else {
            continue;
        };
        let ratio = ratio_to(rows, row, t.against);
        let ok = ratio.is_some_and(|v| v <= t.max_ratio) && (!t.exact || row.errors == 0);
        met += ok as usize;
        let errors = if t.exact { ", no wrong sign" } else { "" };
        body.push(vec![
            format!("{}/{}", t.family, t.inputs),
            format!("<= {:.1}x {}{}", t.max_ratio, t.against, errors),
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
