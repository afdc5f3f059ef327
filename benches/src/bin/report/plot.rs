//! One SVG per family: time per operation (log x) against the fraction of
//! wrong answers (log y), with zero errors in a band of their own below,
//! since a log axis has no place for zero. Colour is the method, the marker
//! shape the inputs.

use crate::framework::Row;

const WIDTH: f64 = 780.0;
const HEIGHT: f64 = 470.0;
const LEFT: f64 = 70.0;
const RIGHT: f64 = 560.0;
const TOP: f64 = 40.0;
const LOG_BOTTOM: f64 = 350.0;
const ZERO_TOP: f64 = 365.0;
const ZERO_BOTTOM: f64 = 420.0;

const COLOURS: [&str; 8] = [
    "#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd", "#8c564b", "#e377c2", "#17becf",
];

/// Values in first-seen order.
fn distinct<'a>(values: impl Iterator<Item = &'a str>) -> Vec<&'a str> {
    let mut out: Vec<&str> = Vec::new();
    for v in values {
        if !out.contains(&v) {
            out.push(v);
        }
    }
    out
}

fn marker(shape: usize, x: f64, y: f64, colour: &str, title: &str) -> String {
    let style = format!(r##"fill="{colour}" fill-opacity="0.8" stroke="#222" stroke-width="0.8""##);
    let poly = |pts: &[(f64, f64)]| {
        let p: Vec<String> = pts
            .iter()
            .map(|(dx, dy)| format!("{:.1},{:.1}", x + dx, y + dy))
            .collect();
        format!(r#"<polygon points="{}" {style}>"#, p.join(" "))
    };
    let open = match shape % 7 {
        0 => format!(r#"<circle cx="{x:.1}" cy="{y:.1}" r="5" {style}>"#),
        1 => poly(&[(-4.5, -4.5), (4.5, -4.5), (4.5, 4.5), (-4.5, 4.5)]),
        2 => poly(&[(0.0, -6.0), (6.0, 0.0), (0.0, 6.0), (-6.0, 0.0)]),
        3 => poly(&[(0.0, -6.0), (5.5, 4.5), (-5.5, 4.5)]),
        4 => poly(&[(0.0, 6.0), (5.5, -4.5), (-5.5, -4.5)]),
        5 => poly(&[
            (-1.8, -6.0),
            (1.8, -6.0),
            (1.8, -1.8),
            (6.0, -1.8),
            (6.0, 1.8),
            (1.8, 1.8),
            (1.8, 6.0),
            (-1.8, 6.0),
            (-1.8, 1.8),
            (-6.0, 1.8),
            (-6.0, -1.8),
            (-1.8, -1.8),
        ]),
        _ => poly(&[
            (0.0, -6.0),
            (1.8, -1.8),
            (6.0, 0.0),
            (1.8, 1.8),
            (0.0, 6.0),
            (-1.8, 1.8),
            (-6.0, 0.0),
            (-1.8, -1.8),
        ]),
    };
    let tag = if shape.is_multiple_of(7) {
        "circle"
    } else {
        "polygon"
    };
    format!("{open}<title>{title}</title></{tag}>\n")
}

fn text(x: f64, y: f64, anchor: &str, size: u32, s: &str) -> String {
    format!(r#"<text x="{x:.1}" y="{y:.1}" text-anchor="{anchor}" font-size="{size}">{s}</text>"#)
        + "\n"
}

fn line(x1: f64, y1: f64, x2: f64, y2: f64, style: &str) -> String {
    format!(r#"<line x1="{x1:.1}" y1="{y1:.1}" x2="{x2:.1}" y2="{y2:.1}" {style}/>"#) + "\n"
}

/// The plot of one family's rows.
pub fn svg(family: &str, rows: &[&Row]) -> String {
    let methods = distinct(rows.iter().map(|r| r.method.as_str()));
    let inputs = distinct(rows.iter().map(|r| r.inputs.as_str()));
    let frac = |r: &Row| r.errors as f64 / r.cases.max(1) as f64;

    let (lo_ns, hi_ns) = rows.iter().fold((f64::MAX, f64::MIN), |(lo, hi), r| {
        (lo.min(r.ns_per_op), hi.max(r.ns_per_op))
    });
    let x_lo = lo_ns.log10().floor();
    let x_hi = hi_ns.log10().ceil().max(x_lo + 1.0);
    let most_cases = rows.iter().map(|r| r.cases).max().unwrap_or(1) as f64;
    let least_wrong = rows
        .iter()
        .map(|r| frac(r))
        .filter(|&f| f > 0.0)
        .fold(1.0, f64::min);
    let y_lo = least_wrong.min(1.0 / most_cases).log10().floor().min(-1.0);
    // Data stay a marker's width inside the axes.
    let pad = 10.0;
    let x_of =
        |ns: f64| LEFT + pad + (ns.log10() - x_lo) / (x_hi - x_lo) * (RIGHT - LEFT - 2.0 * pad);
    let y_of = |f: f64| TOP + pad + (-f.log10()) / (-y_lo) * (LOG_BOTTOM - TOP - pad);

    let mut s = format!(
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{WIDTH}" height="{HEIGHT}" font-family="sans-serif">"#
    );
    s += "\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
    let cases = rows.first().map_or(0, |r| r.cases);
    s += &text(
        LEFT,
        22.0,
        "start",
        15,
        &format!("{family}: time against wrong answers ({cases} cases per point)"),
    );
    let grid = r##"stroke="#ddd" stroke-width="1""##;
    let minor_grid = r##"stroke="#f0f0f0" stroke-width="1""##;
    for d in (x_lo as i32)..=(x_hi as i32) {
        let x = x_of(10f64.powi(d));
        s += &line(x, TOP, x, ZERO_BOTTOM, grid);
        s += &text(
            x,
            ZERO_BOTTOM + 16.0,
            "middle",
            11,
            &format!("{}", 10f64.powi(d)),
        );
        if d < x_hi as i32 {
            for m in 2..10 {
                let x = x_of(m as f64 * 10f64.powi(d));
                s += &line(x, TOP, x, ZERO_BOTTOM, minor_grid);
            }
        }
    }
    for d in (y_lo as i32)..=0 {
        let y = y_of(10f64.powi(d));
        s += &line(LEFT, y, RIGHT, y, grid);
        let label = match d {
            0 => "1".to_string(),
            -1 => "0.1".to_string(),
            -2 => "0.01".to_string(),
            _ => format!("1e{d}"),
        };
        s += &text(LEFT - 6.0, y + 4.0, "end", 11, &label);
    }
    s += &format!(
        "<rect x=\"{LEFT}\" y=\"{ZERO_TOP}\" width=\"{}\" height=\"{}\" fill=\"#eaf6ea\" stroke=\"#9c9\"/>\n",
        RIGHT - LEFT,
        ZERO_BOTTOM - ZERO_TOP
    );
    s += &text(
        LEFT - 6.0,
        (ZERO_TOP + ZERO_BOTTOM) / 2.0 + 4.0,
        "end",
        12,
        "0",
    );
    s += &line(LEFT, TOP, LEFT, LOG_BOTTOM, r#"stroke="black""#);
    s += &text(
        (LEFT + RIGHT) / 2.0,
        HEIGHT - 12.0,
        "middle",
        12,
        "ns per operation (log scale)",
    );
    s += &format!(
        "<text x=\"18\" y=\"{:.1}\" text-anchor=\"middle\" font-size=\"12\" transform=\"rotate(-90 18 {:.1})\">fraction of wrong answers (log scale; 0 in the band)</text>\n",
        (TOP + ZERO_BOTTOM) / 2.0,
        (TOP + ZERO_BOTTOM) / 2.0
    );

    for r in rows {
        let m = methods.iter().position(|&m| m == r.method).unwrap_or(0);
        let i = inputs.iter().position(|&i| i == r.inputs).unwrap_or(0);
        let f = frac(r);
        // Within the zero band, spread the inputs apart so markers overlap less.
        let y = if f > 0.0 {
            y_of(f)
        } else {
            ZERO_TOP + (i as f64 + 1.0) * (ZERO_BOTTOM - ZERO_TOP) / (inputs.len() as f64 + 1.0)
        };
        let title = format!(
            "{} on {}: {:.3} ns/op, {} of {} wrong",
            r.method, r.inputs, r.ns_per_op, r.errors, r.cases
        );
        s += &marker(i, x_of(r.ns_per_op), y, COLOURS[m % COLOURS.len()], &title);
    }

    let lx = RIGHT + 30.0;
    let mut ly = TOP;
    s += &text(lx, ly, "start", 13, "method");
    for (k, m) in methods.iter().enumerate() {
        ly += 20.0;
        s += &marker(0, lx + 8.0, ly - 4.0, COLOURS[k % COLOURS.len()], m);
        s += &text(lx + 22.0, ly, "start", 12, m);
    }
    ly += 34.0;
    s += &text(lx, ly, "start", 13, "inputs");
    for (k, i) in inputs.iter().enumerate() {
        ly += 20.0;
        s += &marker(k, lx + 8.0, ly - 4.0, "#bbb", i);
        s += &text(lx + 22.0, ly, "start", 12, i);
    }
    s + "</svg>\n"
}
