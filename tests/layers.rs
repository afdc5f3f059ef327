//! The floors of `src/` (ARCHITECTURE.md), held by a test: every path to
//! `crate::...` in the library's code (its `#[cfg(test)]` modules aside)
//! must lead to the same floor or one below, nothing in the library may
//! lean on the `testing` or `prelude` doors, and no two files may import
//! each other round a circle (a file and the modules it contains aside:
//! a parent re-exports its children's items and they use its own).
//!
//! Floors, lowest first:
//!
//! | floor | modules |
//! |---|---|
//! | 0 | `error`, `sign`, `point` (conversions), `interval` |
//! | 1 | `arith` |
//! | 2 | `predicates`, `roots` |
//! | 3 | `shape` |
//! | 4 | `query`, `raster` |
//! | 5 | `bvh` |
//! | 6 | `scene` |
//!
//! `testing` and `prelude` stand on the side: they may use every floor.

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

const FLOORS: [&[&str]; 7] = [
    &["error", "sign", "point", "interval"],
    &["arith"],
    &["predicates", "roots"],
    &["shape"],
    &["query", "raster"],
    &["bvh"],
    &["scene"],
];
const SIDE: [&str; 2] = ["testing", "prelude"];

fn floor(module: &str) -> Option<usize> {
    FLOORS.iter().position(|f| f.contains(&module))
}

/// Every `.rs` file below `dir`.
fn sources(dir: &Path, out: &mut Vec<PathBuf>) {
    for entry in std::fs::read_dir(dir).expect("src/ is readable") {
        let path = entry.expect("a directory entry").path();
        if path.is_dir() {
            sources(&path, out);
        } else if path.extension().is_some_and(|e| e == "rs") {
            out.push(path);
        }
    }
}

/// The module path of a file: `src/a/b.rs` and `src/a/b/mod.rs` are
/// `["a", "b"]`, `src/lib.rs` is `[]`.
fn module_of(src: &Path, file: &Path) -> Vec<String> {
    let rel = file.strip_prefix(src).expect("below src/");
    let mut parts: Vec<String> = rel
        .iter()
        .map(|p| p.to_string_lossy().trim_end_matches(".rs").to_string())
        .collect();
    if matches!(parts.last().map(String::as_str), Some("mod" | "lib")) {
        parts.pop();
    }
    parts
}

/// The code of a file without comments and without its `#[cfg(test)]`
/// items (they may use what they test from anywhere).
fn library_code(text: &str) -> String {
    let mut code = String::new();
    let mut skip_depth: Option<usize> = None;
    let mut pending_test = false;
    let mut depth = 0usize;
    for line in text.lines() {
        let line = line.split("//").next().unwrap_or("");
        let trimmed = line.trim();
        if trimmed.starts_with("#[cfg(test)]") {
            pending_test = true;
            continue;
        }
        let opens = line.matches('{').count();
        let closes = line.matches('}').count();
        if pending_test && skip_depth.is_none() {
            pending_test = false;
            if opens > closes {
                skip_depth = Some(depth);
            } else {
                // A one-line test item (a `use` or a `mod x;`).
                depth = depth + opens - closes.min(depth + opens);
                continue;
            }
        }
        depth = (depth + opens).saturating_sub(closes);
        match skip_depth {
            Some(d) if depth <= d => skip_depth = None,
            Some(_) => {}
            None => {
                code.push_str(line);
                code.push('\n');
            }
        }
    }
    code
}

/// Every path `crate::a::b::...` and `super::...` in `code`, resolved to a
/// module path (as far as it names modules or items); a brace group
/// `crate::a::{b, c::d}` gives one path per item.
fn references(code: &str, module: &[String]) -> Vec<Vec<String>> {
    let chars: Vec<char> = code.chars().collect();
    let mut out = Vec::new();
    let mut i = 0;
    while i < chars.len() {
        let boundary = i == 0 || !is_ident(chars[i - 1]);
        let ahead: String = chars[i..chars.len().min(i + 7)].iter().collect();
        let base = match ahead.as_str() {
            "crate::" if boundary => Vec::new(),
            // `super` of module `a::b` (`a/b.rs` or `a/b/mod.rs`) is `a`.
            "super::" if boundary => module[..module.len().saturating_sub(1)].to_vec(),
            _ => {
                i += 1;
                continue;
            }
        };
        i = path_at(&chars, i + 7, base, &mut out);
    }
    out
}

fn is_ident(c: char) -> bool {
    c.is_ascii_alphanumeric() || c == '_'
}

/// Reads `ident::ident::...` (or a brace group after `::`) from `j`,
/// below `path`; pushes what it names to `out`, returns where it stopped.
fn path_at(
    chars: &[char],
    mut j: usize,
    mut path: Vec<String>,
    out: &mut Vec<Vec<String>>,
) -> usize {
    loop {
        while j < chars.len() && chars[j].is_whitespace() {
            j += 1;
        }
        if j < chars.len() && chars[j] == '{' {
            j += 1;
            loop {
                j = path_at(chars, j, path.clone(), out);
                while j < chars.len() && (chars[j].is_whitespace() || chars[j] == ',') {
                    j += 1;
                }
                if j >= chars.len() || chars[j] == '}' {
                    return j + 1;
                }
                if !is_ident(chars[j]) && chars[j] != '{' {
                    // `self`, `*` or an alias's tail: skip one character.
                    j += 1;
                }
            }
        }
        let start = j;
        while j < chars.len() && is_ident(chars[j]) {
            j += 1;
        }
        if j == start {
            break;
        }
        let name: String = chars[start..j].iter().collect();
        match name.as_str() {
            "super" => {
                path.pop();
            }
            "self" => {}
            _ => path.push(name),
        }
        if j + 1 < chars.len() && chars[j] == ':' && chars[j + 1] == ':' {
            j += 2;
        } else {
            break;
        }
    }
    out.push(path);
    j
}

struct Tree {
    src: PathBuf,
    /// Module path -> its file.
    files: BTreeMap<Vec<String>, PathBuf>,
}

impl Tree {
    fn load() -> Tree {
        let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
        let mut all = Vec::new();
        sources(&src, &mut all);
        let files = all.into_iter().map(|f| (module_of(&src, &f), f)).collect();
        Tree { src, files }
    }

    /// The file of the longest module prefix of `path`.
    fn file_of(&self, path: &[String]) -> Option<&Vec<String>> {
        (1..=path.len())
            .rev()
            .find_map(|n| self.files.get_key_value(&path[..n]).map(|(k, _)| k))
    }

    /// The modules of files declared under `#[cfg(test)]` in their
    /// parent (`#[cfg(test)] mod tests;`): test code, as a `#[cfg(test)]`
    /// block inside a file is.
    fn test_files(&self) -> BTreeSet<Vec<String>> {
        let mut tests = BTreeSet::new();
        for (module, file) in &self.files {
            let text = std::fs::read_to_string(file).expect("a source file");
            let mut pending = false;
            for line in text.lines().map(str::trim) {
                if line.starts_with("#[cfg(test)]") {
                    pending = true;
                    continue;
                }
                if pending
                    && let Some(name) = line.strip_prefix("mod ").and_then(|r| r.strip_suffix(';'))
                {
                    let mut child = module.clone();
                    child.push(name.trim().to_string());
                    tests.insert(child);
                }
                pending = false;
            }
        }
        tests
    }

    /// Each file's module and the modules (files) its library code refers to.
    fn edges(&self) -> BTreeMap<Vec<String>, BTreeSet<Vec<String>>> {
        let mut edges = BTreeMap::new();
        let tests = self.test_files();
        for (module, file) in &self.files {
            let text = std::fs::read_to_string(file).expect("a source file");
            let is_test = (1..=module.len()).any(|n| tests.contains(&module[..n]));
            let code = if is_test {
                String::new()
            } else {
                library_code(&text)
            };
            let mut to = BTreeSet::new();
            for path in references(&code, module) {
                if let Some(target) = self.file_of(&path)
                    && target != module
                {
                    to.insert(target.clone());
                }
            }
            edges.insert(module.clone(), to);
        }
        edges
    }
}

#[test]
fn no_import_from_a_higher_floor() {
    let tree = Tree::load();
    let mut wrong = Vec::new();
    let mut checked = 0;
    for (from, targets) in tree.edges() {
        let Some(top) = from.first() else { continue };
        if SIDE.contains(&top.as_str()) {
            continue;
        }
        let here = floor(top).unwrap_or_else(|| panic!("module `{top}` has no floor in FLOORS"));
        for to in targets {
            let Some(there_top) = to.first() else {
                continue;
            };
            checked += 1;
            if SIDE.contains(&there_top.as_str()) {
                wrong.push(format!(
                    "{} -> {} (a side door)",
                    from.join("::"),
                    to.join("::")
                ));
                continue;
            }
            let there = floor(there_top)
                .unwrap_or_else(|| panic!("module `{there_top}` has no floor in FLOORS"));
            if there > here {
                wrong.push(format!(
                    "{} (floor {here}) -> {} (floor {there})",
                    from.join("::"),
                    to.join("::")
                ));
            }
        }
    }
    assert!(
        checked > 100,
        "only {checked} imports read: is the parser broken?"
    );
    assert!(
        wrong.is_empty(),
        "imports from a higher floor:\n{}",
        wrong.join("\n")
    );
}

#[test]
fn no_circles_between_files() {
    let tree = Tree::load();
    let edges = tree.edges();
    let related = |a: &[String], b: &[String]| a.starts_with(b) || b.starts_with(a);
    // Depth-first search for a back edge, reporting the first circle.
    fn visit(
        node: &Vec<String>,
        edges: &BTreeMap<Vec<String>, BTreeSet<Vec<String>>>,
        related: &dyn Fn(&[String], &[String]) -> bool,
        stack: &mut Vec<Vec<String>>,
        done: &mut BTreeSet<Vec<String>>,
        circles: &mut Vec<String>,
    ) {
        if done.contains(node) {
            return;
        }
        if let Some(pos) = stack.iter().position(|n| n == node) {
            let names: Vec<String> = stack[pos..].iter().map(|n| n.join("::")).collect();
            circles.push(format!("{} -> {}", names.join(" -> "), node.join("::")));
            return;
        }
        stack.push(node.clone());
        for next in edges.get(node).into_iter().flatten() {
            if !related(node, next) {
                visit(next, edges, related, stack, done, circles);
            }
        }
        stack.pop();
        done.insert(node.clone());
    }
    let mut circles = Vec::new();
    let mut done = BTreeSet::new();
    for node in edges.keys() {
        visit(
            node,
            &edges,
            &related,
            &mut Vec::new(),
            &mut done,
            &mut circles,
        );
    }
    assert!(
        circles.is_empty(),
        "import circles:\n{}",
        circles.join("\n")
    );
    assert!(tree.src.ends_with("src"));
}

#[test]
fn the_parser_sees_an_upward_import() {
    // The checker itself: a made-up file of floor 1 that uses floor 4, and
    // a test module that may.
    let code = library_code(
        "use crate::query::ray::Ray;\n#[cfg(test)]\nmod tests {\n    use crate::bvh::SphereBvh;\n}\n",
    );
    let refs = references(&code, &["arith".to_string()]);
    assert_eq!(
        refs,
        vec![vec!["query".to_string(), "ray".into(), "Ray".into()]]
    );
    let group = references("use super::{a, b::{c, d}};", &["x".into(), "y".into()]);
    let names: Vec<String> = group.iter().map(|p| p.join("::")).collect();
    assert_eq!(names, ["x::a", "x::b::c", "x::b::d"]);
}
