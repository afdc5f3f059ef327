//! The report's table (terminal and markdown) and `report.json`.

use crate::framework::Row;

/// Time of `row` over the time of `baseline` on the same family and inputs.
pub fn ratio_to(rows: &[Row], row: &Row, baseline: &str) -> Option<f64> {
    rows.iter()
        .find(|r| r.family == row.family && r.inputs == row.inputs && r.method == baseline)
        .map(|b| row.ns_per_op / b.ns_per_op)
}

/// A time in ns with as many digits as matter.
pub fn ns(v: f64) -> String {
    if v < 10.0 {
        format!("{v:.2}")
    } else if v < 1000.0 {
        format!("{v:.1}")
    } else {
        format!("{v:.0}")
    }
}

fn ratio(v: Option<f64>) -> String {
    v.map_or("-".to_string(), |v| format!("{v:.2}x"))
}

fn wrong(errors: u64, cases: u64) -> String {
    if errors == 0 {
        return "0".to_string();
    }
    let pct = 100.0 * errors as f64 / cases as f64;
    if pct >= 1.0 {
        format!("{pct:.1}%")
    } else {
        format!("{pct:.2e}%")
    }
}

/// A markdown table whose columns are padded, so it reads on a terminal too.
pub fn markdown(header: &[&str], body: &[Vec<String>]) -> String {
    let widths: Vec<usize> = (0..header.len())
        .map(|i| {
            body.iter()
                .map(|r| r[i].chars().count())
                .chain([header[i].len()])
                .max()
                .unwrap_or(0)
        })
        .collect();
    let line = |cells: Vec<String>| {
        let padded: Vec<String> = cells
            .iter()
            .zip(&widths)
            .map(|(c, &w)| format!("{c:<w$}"))
            .collect();
        format!("| {} |\n", padded.join(" | "))
    };
    let mut out = line(header.iter().map(|h| h.to_string()).collect());
    out += &line(widths.iter().map(|&w| "-".repeat(w)).collect());
    for r in body {
        out += &line(r.clone());
    }
    out
}

/// The main table: one line per row, with its time relative to `naive` and
/// to `robust` on the same inputs.
pub fn table(rows: &[Row]) -> String {
    let header = [
        "family",
        "inputs",
        "method",
        "ns/op",
        "vs naive",
        "vs robust",
        "cases",
        "errors",
        "wrong",
    ];
    let body: Vec<Vec<String>> = rows
        .iter()
        .map(|r| {
            vec![
                r.family.to_string(),
                r.inputs.clone(),
                r.method.clone(),
                ns(r.ns_per_op),
                ratio(ratio_to(rows, r, "naive")),
                ratio(ratio_to(rows, r, "robust")),
                r.cases.to_string(),
                r.errors.to_string(),
                wrong(r.errors, r.cases),
            ]
        })
        .collect();
    markdown(&header, &body)
}

/// `report.json`: the rows with exactly the fields `docs/report.md` names, in its
/// order (a `serde_json` map would sort them).
pub fn json(rows: &[Row]) -> String {
    let s = |v: &str| serde_json::to_string(v).expect("a string serializes");
    // Four significant digits: more would be timing noise.
    let num = |v: f64| {
        let digits = 3 - v.abs().log10().floor().clamp(-300.0, 300.0) as i32;
        let rounded = if digits > 0 {
            format!("{v:.*}", digits as usize)
        } else {
            format!("{v:.0}")
        };
        serde_json::to_string(&rounded.parse::<f64>().unwrap_or(v)).expect("a number serializes")
    };
    let lines: Vec<String> = rows
        .iter()
        .map(|r| {
            format!(
                "  {{\"family\": {}, \"method\": {}, \"inputs\": {}, \"ns_per_op\": {}, \"cases\": {}, \"errors\": {}, \"max_ulps\": {}, \"max_bound_ulps\": {}}}",
                s(r.family),
                s(&r.method),
                s(&r.inputs),
                num(r.ns_per_op),
                r.cases,
                r.errors,
                r.max_ulps.map_or("null".to_string(), num),
                r.max_bound_ulps.map_or("null".to_string(), num),
            )
        })
        .collect();
    format!("[\n{}\n]\n", lines.join(",\n"))
}
