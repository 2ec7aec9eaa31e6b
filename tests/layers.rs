//! The house's rules, read from the source (docs/DESIGN.md §2, §19):
//!
//! - **Layers.** Each folder of `crate/` belongs to a layer and imports only
//!   from its own layer or those below it: `base` → the controllers
//!   (`funnelling`, `avoidance`, `crowd`, `wander`) → `world` → `studies` →
//!   `cli`, `bindings` → `bin`.
//! - **No cycles** between files, nor between the folders and files that
//!   share a parent folder (two controllers may use each other in one
//!   direction only).
//! - **Steps with names**: no function longer than 150 lines outside tests.
//! - **Today's reasons**: no comment in the code says "issue N" or "stop N";
//!   the git log keeps the history.
//!
//! An import is a path in code (comments and strings stripped) that starts
//! with `crate::`, `super::` or `self::`, or, in a `mod.rs` or `lib.rs`, with
//! the name of a child module. It is resolved to the longest prefix that
//! names a file. A failure names the file and line of every offending path.

#![cfg(not(target_arch = "wasm32"))]

use std::collections::{BTreeMap, BTreeSet};
use std::fs;
use std::path::{Path, PathBuf};

/// The layer of each top folder of `crate/` (`lib.rs`, the root, is above all).
const LAYERS: &[(&str, u32)] = &[
    ("base", 0),
    ("funnelling", 1),
    ("avoidance", 1),
    ("crowd", 1),
    ("wander", 1),
    ("world", 2),
    ("studies", 3),
    ("cli", 4),
    ("bindings", 4),
    ("bin", 5),
];
const ROOT_LAYER: u32 = 6;

/// Longest function allowed outside tests, in lines (signature to closing brace).
const MAX_FN_LINES: usize = 150;

fn crate_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("crate")
}

/// Every `.rs` file under `dir`, as paths relative to `crate/` with `/`.
fn rust_files(dir: &Path, base: &Path, out: &mut Vec<String>) {
    let mut entries: Vec<_> = fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .collect();
    entries.sort();
    for p in entries {
        if p.is_dir() {
            rust_files(&p, base, out);
        } else if p.extension().is_some_and(|e| e == "rs") {
            let rel = p
                .strip_prefix(base)
                .unwrap()
                .to_string_lossy()
                .replace('\\', "/");
            out.push(rel);
        }
    }
}

/// The source with comments and string / char literals blanked (same
/// length, newlines kept), so positions still give line numbers.
fn code_only(src: &str) -> String {
    let b = src.as_bytes();
    let mut out = Vec::with_capacity(b.len());
    let mut i = 0;
    let blank = |c: u8| if c == b'\n' { b'\n' } else { b' ' };
    while i < b.len() {
        let c = b[i];
        if c == b'/' && b.get(i + 1) == Some(&b'/') {
            while i < b.len() && b[i] != b'\n' {
                out.push(b' ');
                i += 1;
            }
        } else if c == b'/' && b.get(i + 1) == Some(&b'*') {
            let mut depth = 0;
            while i < b.len() {
                if b[i] == b'/' && b.get(i + 1) == Some(&b'*') {
                    depth += 1;
                    out.extend([b' ', b' ']);
                    i += 2;
                } else if b[i] == b'*' && b.get(i + 1) == Some(&b'/') {
                    depth -= 1;
                    out.extend([b' ', b' ']);
                    i += 2;
                    if depth == 0 {
                        break;
                    }
                } else {
                    out.push(blank(b[i]));
                    i += 1;
                }
            }
        } else if c == b'r'
            && (b.get(i + 1) == Some(&b'"') || b.get(i + 1) == Some(&b'#'))
            && (i == 0 || !(b[i - 1].is_ascii_alphanumeric() || b[i - 1] == b'_'))
        {
            // A raw string: r"..." or r#"..."#.
            let mut j = i + 1;
            let mut hashes = 0;
            while b.get(j) == Some(&b'#') {
                hashes += 1;
                j += 1;
            }
            if b.get(j) != Some(&b'"') {
                out.push(c);
                i += 1;
                continue;
            }
            let close: Vec<u8> = std::iter::once(b'"')
                .chain(std::iter::repeat_n(b'#', hashes))
                .collect();
            out.extend(std::iter::repeat_n(b' ', j + 1 - i));
            i = j + 1;
            while i < b.len() && !b[i..].starts_with(&close) {
                out.push(blank(b[i]));
                i += 1;
            }
            out.extend(std::iter::repeat_n(b' ', close.len().min(b.len() - i)));
            i += close.len();
        } else if c == b'"' {
            out.push(b' ');
            i += 1;
            while i < b.len() && b[i] != b'"' {
                if b[i] == b'\\' {
                    out.push(b' ');
                    i += 1;
                }
                if i < b.len() {
                    out.push(blank(b[i]));
                    i += 1;
                }
            }
            out.push(b' ');
            i += 1;
        } else if c == b'\'' {
            // A char literal ('a', '\n', '\u{..}') or a lifetime ('a).
            let end = if b.get(i + 1) == Some(&b'\\') {
                b[i + 2..]
                    .iter()
                    .position(|&x| x == b'\'')
                    .map(|p| i + 2 + p)
            } else if b.get(i + 2) == Some(&b'\'') {
                Some(i + 2)
            } else {
                None
            };
            match end {
                Some(e) => {
                    out.extend(std::iter::repeat_n(b' ', e + 1 - i));
                    i = e + 1;
                }
                None => {
                    out.push(c);
                    i += 1;
                }
            }
        } else {
            out.push(c);
            i += 1;
        }
    }
    out.truncate(b.len());
    String::from_utf8(out).unwrap()
}

/// The module path of a file (`world/mod.rs` → `["world"]`, `lib.rs` → `[]`).
fn module_of(file: &str) -> Vec<String> {
    let mut parts: Vec<String> = file
        .trim_end_matches(".rs")
        .split('/')
        .map(String::from)
        .collect();
    if matches!(parts.last().map(String::as_str), Some("mod" | "lib")) {
        parts.pop();
    }
    parts
}

/// The file that defines the longest prefix of `path` (module segments),
/// if any.
fn resolve(files: &BTreeSet<String>, path: &[String]) -> Option<String> {
    for n in (0..=path.len()).rev() {
        let p = path[..n].join("/");
        if n == 0 {
            return Some("lib.rs".into());
        }
        for cand in [format!("{p}.rs"), format!("{p}/mod.rs")] {
            if files.contains(&cand) {
                return Some(cand);
            }
        }
    }
    None
}

fn top_folder(file: &str) -> &str {
    file.split_once('/').map_or("", |(top, _)| top)
}

fn layer(file: &str) -> u32 {
    let top = top_folder(file);
    LAYERS
        .iter()
        .find(|(f, _)| *f == top)
        .map_or(ROOT_LAYER, |&(_, l)| l)
}

/// One import: where it is written and the file it resolves to.
#[derive(Clone, Debug)]
struct Import {
    from: String,
    line: usize,
    path: String,
    to: String,
}

fn is_ident(c: u8) -> bool {
    c.is_ascii_alphanumeric() || c == b'_'
}

/// The path starting at byte `i` (`a::b::{c, d}` stops at the brace), and
/// the byte after its last segment.
fn path_at(code: &[u8], mut i: usize) -> (Vec<String>, usize) {
    let mut segs = Vec::new();
    loop {
        let start = i;
        while i < code.len() && is_ident(code[i]) {
            i += 1;
        }
        if i == start {
            break;
        }
        segs.push(String::from_utf8_lossy(&code[start..i]).into_owned());
        let end = i;
        if code[i..].starts_with(b"::") {
            i += 2;
            while i < code.len() && code[i].is_ascii_whitespace() {
                i += 1;
            }
            if i == code.len() || !is_ident(code[i]) {
                return (segs, end);
            }
        } else {
            return (segs, end);
        }
    }
    (segs, i)
}

/// The paths of a use tree's brace group starting at byte `i` (just after
/// `prefix::{`): `a::{b, c::{d, e}}` gives `a::b`, `a::c::d`, `a::c::e`.
fn brace_paths(code: &[u8], mut i: usize, prefix: &[String], out: &mut Vec<Vec<String>>) -> usize {
    loop {
        while i < code.len() && (code[i].is_ascii_whitespace() || code[i] == b',') {
            i += 1;
        }
        if i >= code.len() || code[i] == b'}' {
            return i + 1;
        }
        let (segs, end) = path_at(code, i);
        let mut full = prefix.to_vec();
        full.extend(segs.iter().cloned());
        let mut j = end;
        while j < code.len() && (code[j].is_ascii_whitespace() || code[j] == b':') {
            j += 1;
        }
        if code.get(j) == Some(&b'{') {
            i = brace_paths(code, j + 1, &full, out);
        } else {
            out.push(full);
            // Skip `as alias` or `*` up to the next separator.
            i = end.max(i + 1);
            while i < code.len() && code[i] != b',' && code[i] != b'}' {
                i += 1;
            }
        }
    }
}

/// Depth of inline `mod name { ... }` blocks at each byte (so that `super`
/// inside `mod tests` means the file itself).
fn inline_mod_depth(code: &[u8]) -> Vec<u8> {
    let mut depth = vec![0u8; code.len()];
    let mut braces: Vec<bool> = Vec::new();
    let mut pending_mod = false;
    let mut cur = 0u8;
    let mut i = 0;
    while i < code.len() {
        let c = code[i];
        if code[i..].starts_with(b"mod ") && (i == 0 || !is_ident(code[i - 1])) {
            pending_mod = true;
        } else if c == b';' {
            pending_mod = false;
        } else if c == b'{' {
            braces.push(pending_mod);
            if pending_mod {
                cur += 1;
            }
            pending_mod = false;
        } else if c == b'}' && braces.pop() == Some(true) {
            cur -= 1;
        }
        depth[i] = cur;
        i += 1;
    }
    depth
}

fn imports_of(files: &BTreeSet<String>, file: &str, src: &str) -> Vec<Import> {
    let code = code_only(src);
    let b = code.as_bytes();
    let depth = inline_mod_depth(b);
    let here = module_of(file);
    let is_mod_root = file.ends_with("mod.rs") || file == "lib.rs";
    let children: BTreeSet<String> = if is_mod_root {
        files
            .iter()
            .filter_map(|f| {
                let m = module_of(f);
                (m.len() == here.len() + 1 && m[..here.len()] == here[..])
                    .then(|| m[here.len()].clone())
            })
            .collect()
    } else {
        BTreeSet::new()
    };
    let mut out = Vec::new();
    let line_of = |i: usize| code[..i].bytes().filter(|&c| c == b'\n').count() + 1;
    let mut i = 0;
    while i < b.len() {
        if !is_ident(b[i]) || (i > 0 && (is_ident(b[i - 1]) || b[i - 1] == b':')) {
            i += 1;
            continue;
        }
        let (segs, mut end) = path_at(b, i);
        // `prefix::{a, b::c}`: each leaf of the use tree is a path of its own.
        let mut j = end;
        while j < b.len() && (b[j].is_ascii_whitespace() || b[j] == b':') {
            j += 1;
        }
        let mut paths = vec![segs.clone()];
        if b[end..].starts_with(b"::") && b.get(j) == Some(&b'{') {
            paths.clear();
            end = brace_paths(b, j + 1, &segs, &mut paths);
        }
        for segs in paths {
            if let Some(im) = import_of(
                files,
                file,
                &here,
                &children,
                is_mod_root,
                depth[i] as usize,
                &segs,
                line_of(i),
            ) {
                out.push(im);
            }
        }
        i = end.max(i + 1);
    }
    out
}

/// The import a path written in `file` makes, if it names another file.
#[allow(clippy::too_many_arguments)]
fn import_of(
    files: &BTreeSet<String>,
    file: &str,
    here: &[String],
    children: &BTreeSet<String>,
    is_mod_root: bool,
    inline_depth: usize,
    segs: &[String],
    line: usize,
) -> Option<Import> {
    {
        let first = segs.first().map(String::as_str).unwrap_or("");
        let target: Option<Vec<String>> = match first {
            "crate" if segs.len() > 1 => Some(segs[1..].to_vec()),
            "super" | "self" if segs.len() > 1 => {
                let mut base = here.to_vec();
                let mut k = 0;
                let mut inline = inline_depth;
                while segs.get(k).map(String::as_str) == Some("super") {
                    if inline > 0 {
                        inline -= 1;
                    } else {
                        base.pop();
                    }
                    k += 1;
                }
                if segs[0] == "self" {
                    k = 1;
                }
                base.extend(segs[k..].iter().cloned());
                Some(base)
            }
            name if is_mod_root && children.contains(name) && segs.len() > 1 => {
                // `use child::Item` in a mod.rs / lib.rs; `mod child;` has no `::`.
                let mut base = here.to_vec();
                base.extend(segs.iter().cloned());
                Some(base)
            }
            _ => None,
        };
        let to = resolve(files, &target?)?;
        (to != file).then(|| Import {
            from: file.into(),
            line,
            path: segs.join("::"),
            to,
        })
    }
}

fn all_imports() -> Vec<Import> {
    let dir = crate_dir();
    let mut list = Vec::new();
    rust_files(&dir, &dir, &mut list);
    let files: BTreeSet<String> = list.iter().cloned().collect();
    list.iter()
        .flat_map(|f| imports_of(&files, f, &fs::read_to_string(dir.join(f)).unwrap()))
        .collect()
}

/// The cycles of a directed graph (its strongly connected components of
/// more than one node), by Tarjan's algorithm.
fn cycles(edges: &BTreeMap<String, BTreeSet<String>>) -> Vec<Vec<String>> {
    struct T<'a> {
        e: &'a BTreeMap<String, BTreeSet<String>>,
        index: BTreeMap<String, usize>,
        low: BTreeMap<String, usize>,
        stack: Vec<String>,
        on: BTreeSet<String>,
        out: Vec<Vec<String>>,
    }
    fn visit(t: &mut T, v: &str) {
        let n = t.index.len();
        t.index.insert(v.into(), n);
        t.low.insert(v.into(), n);
        t.stack.push(v.into());
        t.on.insert(v.into());
        for w in t.e.get(v).into_iter().flatten() {
            if !t.index.contains_key(w) {
                visit(t, w);
                let lw = t.low[w];
                let lv = t.low.get_mut(v).unwrap();
                *lv = (*lv).min(lw);
            } else if t.on.contains(w) {
                let iw = t.index[w];
                let lv = t.low.get_mut(v).unwrap();
                *lv = (*lv).min(iw);
            }
        }
        if t.low[v] == t.index[v] {
            let mut comp = Vec::new();
            loop {
                let w = t.stack.pop().unwrap();
                t.on.remove(&w);
                comp.push(w.clone());
                if w == v {
                    break;
                }
            }
            if comp.len() > 1 {
                comp.sort();
                t.out.push(comp);
            }
        }
    }
    let mut t = T {
        e: edges,
        index: BTreeMap::new(),
        low: BTreeMap::new(),
        stack: vec![],
        on: BTreeSet::new(),
        out: vec![],
    };
    let nodes: BTreeSet<String> = edges
        .iter()
        .flat_map(|(k, v)| std::iter::once(k.clone()).chain(v.iter().cloned()))
        .collect();
    for v in &nodes {
        if !t.index.contains_key(v) {
            visit(&mut t, v);
        }
    }
    t.out
}

/// The child of `dir` (a folder path with a trailing `/`, or "" for the
/// root) that holds `file`: a file directly in it, or a subfolder.
fn child_of<'a>(dir: &str, file: &'a str) -> Option<&'a str> {
    let rest = file.strip_prefix(dir)?;
    Some(match rest.find('/') {
        Some(k) => &file[..dir.len() + k + 1],
        None => file,
    })
}

/// Layer violations and cycles, one message per offending import.
fn violations(imports: &[Import]) -> Vec<String> {
    let mut msgs = Vec::new();
    for im in imports {
        let (lf, lt) = (layer(&im.from), layer(&im.to));
        if lt > lf {
            msgs.push(format!(
                "crate/{}:{}: `{}` imports {} (layer {lt}) from {} (layer {lf}): an upward import",
                im.from,
                im.line,
                im.path,
                im.to,
                top_folder(&im.from)
            ));
        }
    }
    // Cycles between the children (files and subfolders) of every folder.
    let mut dirs: BTreeSet<String> = BTreeSet::from([String::new()]);
    for im in imports {
        let mut d = String::new();
        for part in im
            .from
            .split('/')
            .rev()
            .skip(1)
            .collect::<Vec<_>>()
            .into_iter()
            .rev()
        {
            d.push_str(part);
            d.push('/');
            dirs.insert(d.clone());
        }
    }
    for dir in &dirs {
        let mut edges: BTreeMap<String, BTreeSet<String>> = BTreeMap::new();
        let mut witness: BTreeMap<(String, String), &Import> = BTreeMap::new();
        for im in imports {
            if let (Some(a), Some(b)) = (child_of(dir, &im.from), child_of(dir, &im.to)) {
                if a != b {
                    edges.entry(a.into()).or_default().insert(b.into());
                    witness.entry((a.into(), b.into())).or_insert(im);
                }
            }
        }
        for comp in cycles(&edges) {
            let mut lines = vec![format!("a cycle in crate/{dir}: {}", comp.join(", "))];
            for ((a, b), im) in &witness {
                if comp.contains(a) && comp.contains(b) {
                    lines.push(format!(
                        "  crate/{}:{}: `{}` ({a} → {b})",
                        im.from, im.line, im.path
                    ));
                }
            }
            msgs.push(lines.join("\n"));
        }
    }
    msgs
}

#[test]
fn every_import_goes_down_the_layers_without_cycles() {
    let imports = all_imports();
    assert!(
        imports.len() > 300,
        "the scan found only {} imports: is it reading crate/?",
        imports.len()
    );
    let v = violations(&imports);
    assert!(
        v.is_empty(),
        "{} violations of the layers (docs/DESIGN.md §2):\n{}",
        v.len(),
        v.join("\n")
    );
}

#[test]
fn the_checker_sees_an_upward_import_and_a_cycle() {
    let files: BTreeSet<String> = [
        "lib.rs",
        "base/mod.rs",
        "base/angle.rs",
        "base/rng.rs",
        "world/mod.rs",
    ]
    .iter()
    .map(|s| s.to_string())
    .collect();
    let planted = "//! doc: crate::world::World is fine here\nuse crate::world::World;\nuse super::rng::Rng;\n";
    let mut imports = imports_of(&files, "base/angle.rs", planted);
    assert_eq!(imports.len(), 2, "{imports:?}");
    assert_eq!(
        (imports[0].line, imports[0].to.as_str()),
        (2, "world/mod.rs")
    );
    imports.extend(imports_of(
        &files,
        "base/rng.rs",
        "fn f() { crate::base::angle::wrap(1.0); }",
    ));
    let v = violations(&imports);
    assert!(
        v.iter()
            .any(|m| m.contains("crate/base/angle.rs:2") && m.contains("upward")),
        "{v:?}"
    );
    assert!(
        v.iter().any(|m| m.contains("a cycle in crate/base/")),
        "{v:?}"
    );
}

#[test]
fn comments_and_strings_are_not_imports() {
    let code =
        code_only("let s = \"crate::world\"; // crate::world\n/* crate::world */ let c = '\"'; x");
    assert!(!code.contains("world"), "{code}");
    assert!(code.ends_with('x'));
}

/// Lengths of the functions outside `#[cfg(test)]` code, from `fn` to its
/// closing brace.
fn long_functions(file: &str, src: &str) -> Vec<String> {
    let code = code_only(src);
    let lines: Vec<&str> = code.lines().collect();
    let mut out = Vec::new();
    let mut i = 0;
    while i < lines.len() {
        let l = lines[i].trim_start();
        if l.starts_with("#[cfg(test)]") {
            break; // test modules close the file by convention
        }
        let is_fn = l.split("fn ").next().is_some_and(|pre| {
            pre.split_whitespace().all(|w| {
                matches!(
                    w,
                    "pub" | "pub(crate)" | "pub(super)" | "const" | "async" | "unsafe" | "extern"
                )
            })
        }) && l.contains("fn ");
        if is_fn {
            let mut depth = 0i32;
            let mut started = false;
            let mut j = i;
            'scan: while j < lines.len() {
                for c in lines[j].chars() {
                    match c {
                        '{' => {
                            depth += 1;
                            started = true;
                        }
                        '}' => depth -= 1,
                        ';' if !started => break 'scan,
                        _ => {}
                    }
                    if started && depth == 0 {
                        break 'scan;
                    }
                }
                j += 1;
            }
            let n = j + 1 - i;
            if started && n > MAX_FN_LINES {
                let name = l
                    .split("fn ")
                    .nth(1)
                    .unwrap_or("")
                    .split(['(', '<'])
                    .next()
                    .unwrap_or("");
                out.push(format!(
                    "crate/{file}:{}: fn {name} is {n} lines (at most {MAX_FN_LINES})",
                    i + 1
                ));
            }
        }
        i += 1;
    }
    out
}

#[test]
fn no_function_is_longer_than_150_lines() {
    let dir = crate_dir();
    let mut list = Vec::new();
    rust_files(&dir, &dir, &mut list);
    let long: Vec<String> = list
        .iter()
        .flat_map(|f| long_functions(f, &fs::read_to_string(dir.join(f)).unwrap()))
        .collect();
    assert!(
        long.is_empty(),
        "functions waiting for named steps:\n{}",
        long.join("\n")
    );
}

/// A citation of a section of `docs/DESIGN.md`, as the code writes it.
const CITED: &str = concat!("DESIGN", ".md ", "§");

/// The folders whose files may cite `docs/DESIGN.md` sections.
const CITING_DIRS: &[&str] = &[
    "crate",
    "tests",
    "benches",
    "examples",
    "diagnostics",
    "web/src",
    "web/test",
];

/// Every text file under `dir` (relative to the repository root, `/`
/// separators), skipping build output and installed packages.
fn text_files(root: &Path, dir: &str, out: &mut Vec<String>) {
    let Ok(entries) = fs::read_dir(root.join(dir)) else {
        return;
    };
    let mut names: Vec<String> = entries
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    for name in names {
        let rel = format!("{dir}/{name}");
        if root.join(&rel).is_dir() {
            if !["node_modules", "target", "pkg", "dist"].contains(&name.as_str()) {
                text_files(root, &rel, out);
            }
        } else if [".rs", ".ts", ".mjs", ".js", ".md", ".css", ".html", ".json"]
            .iter()
            .any(|x| name.ends_with(x))
        {
            out.push(rel);
        }
    }
}

/// The section numbers `docs/DESIGN.md` defines: headings `## N. Title`.
fn design_sections(design: &str) -> BTreeSet<u32> {
    design
        .lines()
        .filter_map(|l| l.strip_prefix("## "))
        .filter_map(|h| h.split_once(". ").and_then(|(n, _)| n.parse().ok()))
        .collect()
}

/// What is wrong with the design citations of `src` (file `file`): a
/// section number (or range `N–M`) cited after [`CITED`] that `sections`
/// lacks, and any section cited after the bare word (the old shared
/// notes' spelling, whose numbers meant other sections). Comment markers
/// at line starts are dropped and lines joined, so a citation broken
/// across two comment lines is read whole. This file spells the patterns
/// in pieces, so that it passes its own check.
fn bad_citations(file: &str, src: &str, sections: &BTreeSet<u32>) -> Vec<String> {
    // `starts[i]`: where line i + 1 begins in `flat`.
    let (mut flat, mut starts) = (String::new(), Vec::new());
    for l in src.lines() {
        starts.push(flat.len());
        let t = l.trim_start();
        let t = ["//!", "///", "//", "/*", "*"]
            .iter()
            .find_map(|m| t.strip_prefix(m))
            .unwrap_or(t);
        flat.push_str(t.trim());
        flat.push(' ');
    }
    let line = |k: usize| starts.partition_point(|&s| s <= k);
    let mut bad = Vec::new();
    for (k, _) in flat.match_indices(CITED) {
        let file = format!("{file}:{}", line(k));
        let rest = &flat[k + CITED.len()..];
        let first: String = rest.chars().take_while(char::is_ascii_digit).collect();
        let after = &rest[first.len()..];
        let last: String = after
            .strip_prefix('–')
            .or_else(|| after.strip_prefix('-'))
            .map(|r| r.chars().take_while(char::is_ascii_digit).collect())
            .unwrap_or_default();
        let (Ok(a), b) = (first.parse::<u32>(), last.parse::<u32>().ok()) else {
            bad.push(format!(
                "{file}: a citation of docs/DESIGN.md without a section number"
            ));
            continue;
        };
        for n in a..=b.unwrap_or(a).max(a) {
            if !sections.contains(&n) {
                bad.push(format!(
                    "{file}: cites section {n} of docs/DESIGN.md, which has none"
                ));
            }
        }
    }
    let bare = flat
        .match_indices("DESIGN")
        .filter(|&(k, w)| flat[k + w.len()..].trim_start().starts_with('§'));
    for (k, _) in bare {
        bad.push(format!(
            "{file}:{}: cites a section of the design by its bare name: write docs/DESIGN.md and the section",
            line(k)
        ));
    }
    bad
}

#[test]
fn design_citations_name_sections_of_the_design() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let sections = design_sections(&fs::read_to_string(root.join("docs/DESIGN.md")).unwrap());
    assert!(
        (1..=10).all(|n| sections.contains(&n)),
        "docs/DESIGN.md numbers its sections `## N. Title`: {sections:?}"
    );
    let mut files = Vec::new();
    for d in CITING_DIRS {
        text_files(root, d, &mut files);
    }
    let (mut bad, mut cited) = (Vec::new(), 0);
    for f in &files {
        let Ok(src) = fs::read_to_string(root.join(f)) else {
            continue;
        };
        cited += src.matches(CITED).count();
        bad.extend(bad_citations(f, &src, &sections));
    }
    assert!(cited > 20, "only {cited} citations of docs/DESIGN.md seen");
    assert!(
        bad.is_empty(),
        "citations of docs/DESIGN.md that name no section:\n{}",
        bad.join("\n")
    );
}

#[test]
fn the_citation_check_sees_a_missing_section_and_a_bare_citation() {
    let sections = design_sections("# Design\n## 1. One\n## 2. Two\ntext\n### 3. Not a section\n");
    assert_eq!(sections, BTreeSet::from([1, 2]));
    let check = |src: &str| bad_citations("f.rs", src, &sections).len();
    let design = "DESIGN";
    assert_eq!(check(&format!("//! docs/{design}.md §2: fine")), 0);
    assert_eq!(check(&format!("//! docs/{design}.md §1–2, ranges")), 0);
    assert_eq!(check(&format!("//! docs/{design}.md §3")), 1);
    assert_eq!(check(&format!("//! docs/{design}.md §1–3")), 1);
    assert_eq!(check(&format!("//! the ({design}\n//! §2) split")), 1);
    assert_eq!(check(&format!("/// docs/{design}.md\n/// §3 split")), 1);
    assert_eq!(check(&format!("// {design} §1")), 1);
}

/// The word issue or stop followed by a number, case-insensitive.
fn names_history(line: &str) -> bool {
    let lower = line.to_ascii_lowercase();
    let b = lower.as_bytes();
    ["issue ", "stop "].iter().any(|w| {
        lower.match_indices(w).any(|(k, _)| {
            (k == 0 || !is_ident(b[k - 1])) && b.get(k + w.len()).is_some_and(u8::is_ascii_digit)
        })
    })
}

#[test]
fn the_code_says_why_not_when() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut list = Vec::new();
    for d in ["crate", "tests", "benches", "examples", "diagnostics"] {
        let mut files = Vec::new();
        rust_files(&root.join(d), root, &mut files);
        list.extend(files);
    }
    list.extend(["Makefile".to_string(), "Cargo.toml".to_string()]);
    let mut hits = Vec::new();
    for f in &list {
        for (k, line) in fs::read_to_string(root.join(f))
            .unwrap()
            .lines()
            .enumerate()
        {
            if names_history(line) && !line.contains("names_history") {
                hits.push(format!("{f}:{}: {}", k + 1, line.trim()));
            }
        }
    }
    assert!(
        names_history("see Issue 17") && !names_history("reissue 3") && !names_history("stop at 3")
    );
    assert!(
        hits.is_empty(),
        "history in the code (the git log keeps it; say why instead):\n{}",
        hits.join("\n")
    );
}

/// Most lines a file of `crate/` may have before its tests (the
/// `#[cfg(test)]` module that closes it): a file longer than that holds
/// more than one concern, and is split by concern.
const MAX_FILE_LINES: usize = 700;

/// The file's lines before its test module (a `#[cfg(test)]` at the start
/// of a line closes the file by convention), when more than
/// [`MAX_FILE_LINES`]: a message naming the first line over.
fn long_file(file: &str, src: &str) -> Option<String> {
    let n = src
        .lines()
        .position(|l| l.starts_with("#[cfg(test)]"))
        .unwrap_or_else(|| src.lines().count());
    (n > MAX_FILE_LINES).then(|| {
        format!(
            "crate/{file}:{}: {n} lines before its tests (at most {MAX_FILE_LINES}): split it by concern",
            MAX_FILE_LINES + 1
        )
    })
}

#[test]
fn no_file_is_longer_than_700_lines_before_its_tests() {
    let dir = crate_dir();
    let mut list = Vec::new();
    rust_files(&dir, &dir, &mut list);
    let long: Vec<String> = list
        .iter()
        .filter_map(|f| long_file(f, &fs::read_to_string(dir.join(f)).unwrap()))
        .collect();
    assert!(
        long.is_empty(),
        "files holding too much:\n{}",
        long.join("\n")
    );
}

/// Most lines of code (comments and blank lines not counted) in a `mod.rs`.
const MAX_FACE_LINES: usize = 40;

/// What a `mod.rs` may hold besides comments (rapier's model: a short face,
/// the folder's table in its doc comment): `mod name;` declarations, `use`
/// and `pub use` statements and attributes, at most [`MAX_FACE_LINES`]
/// lines of them. A type, function, constant, impl or inline module lives
/// in a file of its own. One message per offending line.
fn face_violations(file: &str, src: &str) -> Vec<String> {
    let code = code_only(src);
    let mut out = Vec::new();
    let mut in_use = false;
    let mut lines = 0;
    for (k, line) in code.lines().enumerate() {
        let l = line.trim();
        if l.is_empty() {
            continue;
        }
        lines += 1;
        if lines == MAX_FACE_LINES + 1 {
            out.push(format!(
                "crate/{file}:{}: more than {MAX_FACE_LINES} lines of code in a mod.rs",
                k + 1
            ));
        }
        if in_use {
            in_use = !l.ends_with(';');
            continue;
        }
        let item = l
            .strip_prefix("pub(crate) ")
            .or_else(|| l.strip_prefix("pub(super) "))
            .or_else(|| l.strip_prefix("pub "))
            .unwrap_or(l);
        let face = if item.starts_with("use ") {
            in_use = !l.ends_with(';');
            true
        } else if item.starts_with("mod ") {
            l.ends_with(';')
        } else {
            (l.starts_with("#[") || l.starts_with("#![")) && l.ends_with(']')
        };
        if !face {
            out.push(format!(
                "crate/{file}:{}: `{l}`: a mod.rs holds only `mod name;`, `use` / `pub use` and attributes (the rest goes in a file named for it)",
                k + 1
            ));
        }
    }
    out
}

#[test]
fn every_mod_rs_is_a_short_face() {
    let dir = crate_dir();
    let mut list = Vec::new();
    rust_files(&dir, &dir, &mut list);
    let v: Vec<String> = list
        .iter()
        .filter(|f| f.ends_with("mod.rs"))
        .flat_map(|f| face_violations(f, &fs::read_to_string(dir.join(f)).unwrap()))
        .collect();
    assert!(
        v.is_empty(),
        "mod.rs files that are more than a face:\n{}",
        v.join("\n")
    );
}

#[test]
fn the_checker_sees_a_long_file_and_a_mod_rs_with_a_body() {
    let src = format!("{}#[cfg(test)]\nmod tests {{}}\n", "//\n".repeat(700));
    assert_eq!(long_file("a.rs", &src), None);
    let msg = long_file("a.rs", &format!("fn f() {{}}\n{src}"));
    assert!(msg.is_some_and(|m| m.starts_with("crate/a.rs:701: 701 lines")));
    let face = "//! | table |\n#[allow(clippy::module_inception)]\nmod a;\npub mod b;\npub use a::{\n    A,\n    B,\n};\n";
    assert!(face_violations("x/mod.rs", face).is_empty());
    let body = format!("{face}pub struct S;\n\nfn f() {{}}\nmod tests {{}}\n");
    let v = face_violations("x/mod.rs", &body);
    assert_eq!(v.len(), 3, "{v:?}");
    assert!(
        v[0].starts_with("crate/x/mod.rs:9: `pub struct S;`"),
        "{v:?}"
    );
    assert!(
        v[2].starts_with("crate/x/mod.rs:12: `mod tests {}`"),
        "{v:?}"
    );
    let long = "use a::b;\n".repeat(41);
    let v = face_violations("x/mod.rs", &long);
    assert!(
        v.len() == 1 && v[0].starts_with("crate/x/mod.rs:41: more than 40"),
        "{v:?}"
    );
}
