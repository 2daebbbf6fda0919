//! Docs that check themselves: `docs/architecture.md` and the prose against
//! the code.
//!
//! - Every direct dependency of the physics core (`[dependencies]` of
//!   `Cargo.toml` without `optional = true`) is named in the "physics core"
//!   row of the table of layers.
//! - Every file under `src/` over [`FILE_LINES`] lines and every function
//!   over [`FN_LINES`] lines (from its `fn` line to its closing brace; test
//!   modules and `tests.rs` files left out) is named under "What remains
//!   long, and why", and everything named there is still that long.
//! - No code or doc cites an issue number or a planning document: the text
//!   says what a thing is, not which ticket asked for it.

use std::path::{Path, PathBuf};

/// Files longer than this are listed in `docs/architecture.md`.
const FILE_LINES: usize = 500;
/// Functions longer than this are listed in `docs/architecture.md`.
const FN_LINES: usize = 100;
/// The heading of the list of long files and functions.
const LONG_HEADING: &str = "## What remains long, and why";

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

fn read(rel: &str) -> String {
    let path = root().join(rel);
    std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

/// The files under `dir` (relative to the root) whose names end in one of
/// `exts`, as sorted paths relative to the root with `/` separators.
fn files_under(dir: &str, exts: &[&str]) -> Vec<String> {
    fn walk(dir: &Path, exts: &[&str], out: &mut Vec<PathBuf>) {
        for e in std::fs::read_dir(dir).unwrap() {
            let p = e.unwrap().path();
            if p.is_dir() {
                walk(&p, exts, out);
            } else if exts.iter().any(|x| p.to_string_lossy().ends_with(x)) {
                out.push(p);
            }
        }
    }
    let mut out = Vec::new();
    walk(&root().join(dir), exts, &mut out);
    let mut rel: Vec<String> = out
        .iter()
        .map(|p| {
            let r = p.strip_prefix(root()).unwrap();
            r.components()
                .map(|c| c.as_os_str().to_string_lossy().into_owned())
                .collect::<Vec<_>>()
                .join("/")
        })
        .collect();
    rel.sort();
    rel
}

/// The text between the line `heading` and the next heading of the same or
/// a higher level.
fn section<'a>(md: &'a str, heading: &str) -> &'a str {
    let start = md
        .find(&format!("\n{heading}\n"))
        .unwrap_or_else(|| panic!("no heading {heading:?}"))
        + heading.len()
        + 2;
    let level = heading.split(' ').next().unwrap();
    let rest = &md[start..];
    let end = rest
        .match_indices('\n')
        .map(|(i, _)| i + 1)
        .find(|&i| {
            let hashes = rest[i..].bytes().take_while(|&b| b == b'#').count();
            hashes > 0 && hashes <= level.len() && rest[i + hashes..].starts_with(' ')
        })
        .unwrap_or(rest.len());
    &rest[..end]
}

/// The `code` spans of a Markdown text.
fn code_spans(md: &str) -> Vec<&str> {
    md.split('`').skip(1).step_by(2).collect()
}

/// Whether a `/`-path matches `pattern`, which may hold one `*` (any run of
/// characters within a file name).
fn path_matches(pattern: &str, path: &str) -> bool {
    match pattern.split_once('*') {
        None => pattern == path,
        Some((head, tail)) => {
            path.len() >= head.len() + tail.len()
                && path.starts_with(head)
                && path.ends_with(tail)
                && !path[head.len()..path.len() - tail.len()].contains('/')
        }
    }
}

// ---------------------------------------------------------------------
// (a) dependencies

/// The direct, non-optional dependencies in a `Cargo.toml` text: the keys
/// of `[dependencies]` (and tables `[dependencies.NAME]`) without
/// `optional = true`.
fn required_dependencies(cargo_toml: &str) -> Vec<String> {
    let mut out: Vec<(String, bool)> = Vec::new();
    let mut table: Option<Option<String>> = None; // Some(None): [dependencies]
    for line in cargo_toml.lines() {
        let t = line.trim();
        if t.starts_with('[') {
            table = if t == "[dependencies]" {
                Some(None)
            } else if let Some(name) = t
                .strip_prefix("[dependencies.")
                .and_then(|r| r.strip_suffix(']'))
            {
                out.push((name.trim().to_string(), false));
                Some(Some(name.trim().to_string()))
            } else {
                None
            };
            continue;
        }
        let code = t.split('#').next().unwrap().trim();
        let Some((key, value)) = code.split_once('=') else {
            continue;
        };
        let optional = |v: &str| v.replace(' ', "").contains("optional=true");
        match &table {
            Some(None) => out.push((key.trim().to_string(), optional(value))),
            Some(Some(name)) if key.trim() == "optional" => {
                let last = out.iter_mut().rev().find(|(n, _)| n == name).unwrap();
                last.1 = value.trim() == "true";
            }
            _ => {}
        }
    }
    out.into_iter()
        .filter(|(_, opt)| !opt)
        .map(|(n, _)| n)
        .collect()
}

/// The "depends on" cell of the row of `layer` in the table of layers.
fn layer_dependencies(md: &str, layer: &str) -> String {
    let row = md
        .lines()
        .find(|l| l.starts_with(&format!("| {layer} |")))
        .unwrap_or_else(|| panic!("no row `| {layer} |` in the table of layers"));
    row.split('|').nth(3).unwrap().to_string()
}

fn words(text: &str) -> Vec<&str> {
    text.split(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
        .filter(|w| !w.is_empty())
        .collect()
}

/// The dependencies of `cargo_toml` missing from the physics core's row.
fn missing_core_dependencies(cargo_toml: &str, md: &str) -> Vec<String> {
    let cell = layer_dependencies(md, "physics core");
    let listed = words(&cell);
    required_dependencies(cargo_toml)
        .into_iter()
        .filter(|d| !listed.contains(&d.as_str()))
        .collect()
}

#[test]
fn the_layer_table_names_every_dependency_of_the_physics_core() {
    let deps = required_dependencies(&read("Cargo.toml"));
    assert!(
        deps.iter().any(|d| d == "rayon") && !deps.iter().any(|d| d == "clap"),
        "the parser of Cargo.toml: {deps:?}"
    );
    let missing = missing_core_dependencies(&read("Cargo.toml"), &read("docs/architecture.md"));
    assert!(
        missing.is_empty(),
        "docs/architecture.md: the physics core's row of the table of layers omits \
         {missing:?} (non-optional [dependencies] of Cargo.toml)"
    );
}

#[test]
fn dependencies_are_read_from_both_forms() {
    let toml = "[package]\nname = \"x\"\n[dependencies]\na = \"1\"\nb = { version = \"1\", optional = true }\n\
                c = { version = \"1\", features = [\"x\"] } # a comment\n[dependencies.d]\nversion = \"1\"\n\
                [dependencies.e]\nversion = \"1\"\noptional = true\n[dev-dependencies]\nf = \"1\"\n";
    assert_eq!(required_dependencies(toml), ["a", "c", "d"]);
    let md = "| layer | where | depends on | builds with |\n|---|---|---|---|\n\
              | physics core | `src/` | a, c | `cargo build` |\n";
    assert_eq!(missing_core_dependencies(toml, md), ["d"]);
}

// ---------------------------------------------------------------------
// (b), (c) long files and functions

/// `src` with comments and the insides of string and character literals
/// replaced by spaces (newlines kept, so byte offsets and line numbers stay
/// those of the source): braces and `fn` in them no longer count.
fn code_only(src: &str) -> Vec<u8> {
    let b = src.as_bytes();
    let mut out = b.to_vec();
    let blank = |out: &mut Vec<u8>, from: usize, to: usize| {
        for c in &mut out[from..to.min(b.len())] {
            if *c != b'\n' {
                *c = b' ';
            }
        }
    };
    let ident = |c: u8| c.is_ascii_alphanumeric() || c == b'_';
    let mut i = 0;
    while i < b.len() {
        let next = b.get(i + 1).copied();
        match b[i] {
            b'/' if next == Some(b'/') => {
                let end = b[i..]
                    .iter()
                    .position(|&c| c == b'\n')
                    .map_or(b.len(), |k| i + k);
                blank(&mut out, i, end);
                i = end;
            }
            b'/' if next == Some(b'*') => {
                let (mut depth, mut j) = (1, i + 2);
                while j < b.len() && depth > 0 {
                    if b[j..].starts_with(b"/*") {
                        depth += 1;
                        j += 2;
                    } else if b[j..].starts_with(b"*/") {
                        depth -= 1;
                        j += 2;
                    } else {
                        j += 1;
                    }
                }
                blank(&mut out, i, j);
                i = j;
            }
            b'"' => {
                let mut j = i + 1;
                while j < b.len() && b[j] != b'"' {
                    j += if b[j] == b'\\' { 2 } else { 1 };
                }
                blank(&mut out, i + 1, j);
                i = j + 1;
            }
            // A raw string r"..." / r#"..."# / br"...".
            b'r' if (i == 0
                || !ident(b[i - 1])
                || (b[i - 1] == b'b' && (i < 2 || !ident(b[i - 2]))))
                && {
                    let hashes = b[i + 1..].iter().take_while(|&&c| c == b'#').count();
                    b.get(i + 1 + hashes) == Some(&b'"')
                } =>
            {
                let hashes = b[i + 1..].iter().take_while(|&&c| c == b'#').count();
                let open = i + 1 + hashes + 1;
                let mut close = vec![b'"'];
                close.extend(std::iter::repeat_n(b'#', hashes));
                let end = (open..b.len())
                    .find(|&j| b[j..].starts_with(&close))
                    .unwrap_or(b.len());
                blank(&mut out, open, end);
                i = end + close.len();
            }
            b'\'' => {
                if next == Some(b'\\') {
                    // '\n', '\'', '\u{..}'
                    let mut j = i + 3;
                    while j < b.len() && b[j] != b'\'' {
                        j += 1;
                    }
                    blank(&mut out, i + 1, j);
                    i = j + 1;
                } else {
                    let len = src[i + 1..].chars().next().map_or(1, char::len_utf8);
                    if b.get(i + 1 + len) == Some(&b'\'') {
                        blank(&mut out, i + 1, i + 1 + len);
                        i += 2 + len;
                    } else {
                        i += 1; // a lifetime or a label
                    }
                }
            }
            _ => i += 1,
        }
    }
    out
}

/// A function of a source file.
#[derive(Debug, Clone, PartialEq)]
struct Function {
    /// The type or trait whose `impl`/`trait` block holds it directly.
    owner: Option<String>,
    name: String,
    /// Lines from the `fn` line to the closing brace, both included.
    lines: usize,
    /// Its `fn` line (1-based).
    line: usize,
}

/// The index of the brace closing the one at `open`.
fn matching_brace(code: &[u8], open: usize) -> usize {
    let mut depth = 0usize;
    for (k, &c) in code[open..].iter().enumerate() {
        match c {
            b'{' => depth += 1,
            b'}' => {
                depth -= 1;
                if depth == 0 {
                    return open + k;
                }
            }
            _ => {}
        }
    }
    code.len() - 1
}

/// From `from`, the first `{` (a body) or `;` (none) outside parentheses
/// and brackets.
fn body_start(code: &[u8], from: usize) -> Option<usize> {
    let mut depth = 0i32;
    for (k, &c) in code[from..].iter().enumerate() {
        match c {
            b'(' | b'[' => depth += 1,
            b')' | b']' => depth -= 1,
            b'{' if depth <= 0 => return Some(from + k),
            b';' if depth <= 0 => return None,
            _ => {}
        }
    }
    None
}

/// The type an `impl` header (between `impl` and its `{`) is for: the last
/// identifier before its generic arguments, after `for` when there is one.
fn impl_owner(header: &str) -> Option<String> {
    let h = header.trim_start();
    // Drop the impl's own generic parameters.
    let mut rest = h;
    if h.starts_with('<') {
        let mut depth = 0;
        let bytes = h.as_bytes();
        for (k, &c) in bytes.iter().enumerate() {
            match c {
                b'<' => depth += 1,
                b'>' if k == 0 || bytes[k - 1] != b'-' => {
                    depth -= 1;
                    if depth == 0 {
                        rest = &h[k + 1..];
                        break;
                    }
                }
                _ => {}
            }
        }
    }
    let rest = rest.split(" where").next().unwrap();
    let ty = match rest.split_once(" for ") {
        Some((_, ty)) => ty,
        None => rest,
    };
    let ty = ty.split('<').next().unwrap();
    words(ty).last().map(|w| w.to_string())
}

/// The functions of one Rust source file with their lengths, `#[cfg(test)]`
/// items left out.
fn functions(src: &str) -> Vec<Function> {
    let code = code_only(src);
    let line_of = |pos: usize| 1 + code[..pos].iter().filter(|&&c| c == b'\n').count();
    let ident = |c: u8| c.is_ascii_alphanumeric() || c == b'_';
    let mut out = Vec::new();
    // Open `impl`/`trait` blocks: (the index of their `{`, their owner).
    let mut owners: Vec<(usize, usize, String)> = Vec::new(); // (open, close, owner)
    let mut cfg_test = false;
    // The last significant byte before the current token, and the last word.
    let mut prev_byte = b'{';
    let mut prev_word = String::new();
    let mut i = 0;
    while i < code.len() {
        let c = code[i];
        if c.is_ascii_whitespace() {
            i += 1;
            continue;
        }
        if c == b'#' && matches!(code.get(i + 1), Some(b'[') | Some(b'!')) {
            let open = i + code[i..].iter().position(|&c| c == b'[').unwrap();
            let mut depth = 0;
            let mut end = open;
            for (k, &c) in code[open..].iter().enumerate() {
                match c {
                    b'[' => depth += 1,
                    b']' => {
                        depth -= 1;
                        if depth == 0 {
                            end = open + k;
                            break;
                        }
                    }
                    _ => {}
                }
            }
            let attr: String = code[open + 1..end]
                .iter()
                .filter(|c| !c.is_ascii_whitespace())
                .map(|&c| c as char)
                .collect();
            if attr == "cfg(test)" {
                cfg_test = true;
            }
            prev_byte = b']';
            i = end + 1;
            continue;
        }
        if ident(c) && (i == 0 || !ident(code[i - 1])) {
            let end = i + code[i..].iter().take_while(|&&c| ident(c)).count();
            let word = std::str::from_utf8(&code[i..end]).unwrap().to_string();
            let item_position = matches!(prev_byte, b'{' | b'}' | b';' | b']' | b')')
                || [
                    "pub", "unsafe", "const", "async", "extern", "default", "auto", "crate",
                ]
                .contains(&prev_word.as_str());
            match word.as_str() {
                "mod" | "fn" | "impl" | "trait" if cfg_test => {
                    // The test-only item: skip its body.
                    cfg_test = false;
                    if let Some(open) = body_start(&code, end) {
                        i = matching_brace(&code, open) + 1;
                        prev_byte = b'}';
                        continue;
                    }
                }
                "fn" => {
                    let name_at = end
                        + code[end..]
                            .iter()
                            .take_while(|c| c.is_ascii_whitespace())
                            .count();
                    let name_end =
                        name_at + code[name_at..].iter().take_while(|&&c| ident(c)).count();
                    if name_end > name_at && !code[name_at].is_ascii_digit() {
                        if let Some(open) = body_start(&code, name_end) {
                            let close = matching_brace(&code, open);
                            let owner = owners
                                .iter()
                                .rev()
                                .find(|(o, e, _)| *o < i && i < *e)
                                .filter(|(o, _, _)| {
                                    // directly in the block: no brace between
                                    // its `{` and this `fn` left open
                                    let mut d = 0i32;
                                    for &c in &code[o + 1..i] {
                                        match c {
                                            b'{' => d += 1,
                                            b'}' => d -= 1,
                                            _ => {}
                                        }
                                    }
                                    d == 0
                                })
                                .map(|(_, _, n)| n.clone());
                            out.push(Function {
                                owner,
                                name: std::str::from_utf8(&code[name_at..name_end])
                                    .unwrap()
                                    .to_string(),
                                lines: line_of(close) - line_of(i) + 1,
                                line: line_of(i),
                            });
                        }
                    }
                }
                "impl" | "trait" if item_position => {
                    if let Some(open) = body_start(&code, end) {
                        let header = std::str::from_utf8(&code[end..open]).unwrap();
                        let owner = if word == "impl" {
                            impl_owner(header)
                        } else {
                            words(header).first().map(|w| w.to_string())
                        };
                        if let Some(owner) = owner {
                            owners.push((open, matching_brace(&code, open), owner));
                        }
                    }
                }
                _ => {}
            }
            prev_word = word;
            prev_byte = b'a';
            i = end;
            continue;
        }
        if matches!(c, b';' | b'{' | b'}') {
            cfg_test = false;
        }
        prev_byte = c;
        prev_word.clear();
        i += 1;
    }
    out
}

/// How a function at `file` is named in the docs: `Owner::name` for a
/// method, `module::name` (the file's module) for any function.
fn names(file: &str, f: &Function) -> Vec<String> {
    let path = Path::new(file);
    let stem = path.file_stem().unwrap().to_string_lossy();
    let module = if ["mod", "main", "lib"].contains(&stem.as_ref()) {
        path.parent()
            .and_then(|p| p.file_name())
            .map_or(stem.to_string(), |p| p.to_string_lossy().into_owned())
    } else {
        stem.to_string()
    };
    let mut out = Vec::new();
    if let Some(owner) = &f.owner {
        out.push(format!("{owner}::{}", f.name));
    }
    out.push(format!("{module}::{}", f.name));
    out
}

/// The long-file and long-function lists of `docs/architecture.md`: the
/// `code` spans of the section before and after its line starting with
/// "Functions over".
fn long_lists(md: &str) -> (Vec<String>, Vec<String>) {
    let s = section(md, LONG_HEADING);
    let split = s
        .find("\nFunctions over")
        .expect("a line starting with \"Functions over\" under \"What remains long\"");
    let spans = |t: &str| {
        code_spans(t)
            .into_iter()
            .map(str::to_string)
            .collect::<Vec<_>>()
    };
    (spans(&s[..split]), spans(&s[split..]))
}

/// The problems of the long lists: long files or functions not named,
/// and named ones that are no longer long. `sources` holds (path, text).
fn long_list_problems(md: &str, sources: &[(String, String)]) -> Vec<String> {
    let (file_spans, fn_spans) = long_lists(md);
    let mut problems = Vec::new();
    let file_patterns: Vec<&String> = file_spans
        .iter()
        .filter(|s| s.starts_with("src/"))
        .collect();
    for (path, text) in sources {
        let n = text.lines().count();
        let named = file_patterns.iter().any(|p| path_matches(p, path));
        if n > FILE_LINES && !named {
            problems.push(format!(
                "{path} has {n} lines: name it (with why) in the list of long files"
            ));
        }
    }
    for p in &file_patterns {
        let matched: Vec<usize> = sources
            .iter()
            .filter(|(path, _)| path_matches(p, path))
            .map(|(_, t)| t.lines().count())
            .collect();
        if matched.is_empty() {
            problems.push(format!("{p}: no such file under src/ (listed as long)"));
        } else if matched.iter().all(|&n| n <= FILE_LINES) {
            problems.push(format!(
                "{p}: {matched:?} lines, no longer over {FILE_LINES}: drop it from the list"
            ));
        }
    }
    let mut long_names = Vec::new();
    for (path, text) in sources {
        if path.ends_with("/tests.rs") {
            continue;
        }
        for f in functions(text) {
            if f.lines <= FN_LINES {
                continue;
            }
            let ns = names(path, &f);
            if !ns.iter().any(|n| fn_spans.contains(n)) {
                problems.push(format!(
                    "{path}:{}: `{}` has {} lines: name it (with why) in the list of long functions",
                    f.line, ns[0], f.lines
                ));
            }
            long_names.extend(ns);
        }
    }
    for s in &fn_spans {
        let is_name = s.contains("::") && words(s).len() == 2 && !s.contains(' ');
        if is_name && !long_names.contains(s) {
            problems.push(format!(
                "`{s}`: not a function over {FN_LINES} lines: drop it from the list"
            ));
        }
    }
    problems
}

fn sources() -> Vec<(String, String)> {
    files_under("src", &[".rs"])
        .into_iter()
        .map(|p| {
            let t = read(&p);
            (p, t)
        })
        .collect()
}

#[test]
fn long_files_and_functions_are_named_in_architecture_md() {
    let problems = long_list_problems(&read("docs/architecture.md"), &sources());
    assert!(
        problems.is_empty(),
        "docs/architecture.md, \"What remains long, and why\":\n{}",
        problems.join("\n")
    );
}

#[test]
fn the_scanner_measures_functions_from_fn_to_closing_brace() {
    let src = r###"
/// A doc comment with fn fake() { and a brace
pub fn free(x: f64) -> f64 {
    let s = "}}} fn not_a_function() {";
    let r = r#"{"#;
    let c = '{';
    let l: &'static str = "x";
    x + 1.0
}

impl<T: Fn() -> f64> Holder<T> where T: Copy {
    fn method(&self) -> impl Fn(f64) -> f64 {
        fn inner() {}
        |x| x
    }
}

impl std::fmt::Display for Error {
    fn fmt(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result { Ok(()) }
}

pub trait Law {
    fn state(&self) -> f64;
    fn pull_off(&self) -> f64 {
        0.0 /* } */
    }
}

#[cfg(test)]
mod tests {
    fn hidden() {}
}
"###;
    let fs = functions(src);
    let got: Vec<(Option<&str>, &str, usize)> = fs
        .iter()
        .map(|f| (f.owner.as_deref(), f.name.as_str(), f.lines))
        .collect();
    assert_eq!(
        got,
        [
            (None, "free", 7),
            (Some("Holder"), "method", 4),
            (None, "inner", 1),
            (Some("Error"), "fmt", 1),
            (Some("Law"), "pull_off", 3),
        ]
    );
    assert_eq!(
        names("src/law/mod.rs", &fs[1]),
        ["Holder::method", "law::method"]
    );
}

#[test]
fn the_long_list_check_fails_on_an_unnamed_or_stale_entry() {
    let body = |n: usize| format!("fn long() {{\n{}}}\n", "    let x = 1;\n".repeat(n));
    let sources = vec![
        ("src/a.rs".to_string(), body(FN_LINES)), // 102 lines: file short, fn long
        ("src/b.rs".to_string(), "\n".repeat(FILE_LINES + 1)), // a long file
    ];
    let md = |files: &str, fns: &str| {
        format!("# A\n\n{LONG_HEADING}\nFiles over 500 lines:\n{files}\nFunctions over 100 lines:\n{fns}\n\n## Next\n")
    };
    assert!(long_list_problems(&md("- `src/b.rs`: why", "- `a::long`: why"), &sources).is_empty());
    let p = long_list_problems(&md("", "- `a::long`"), &sources);
    assert!(
        p.len() == 1 && p[0].contains("src/b.rs has 501 lines"),
        "{p:?}"
    );
    let p = long_list_problems(&md("- `src/b.rs`", ""), &sources);
    assert!(
        p.len() == 1 && p[0].contains("`a::long` has 102 lines"),
        "{p:?}"
    );
    let p = long_list_problems(
        &md("- `src/b.rs`, `src/a.rs`", "- `a::long`, `a::gone`"),
        &sources,
    );
    assert_eq!(p.len(), 2, "{p:?}");
}

// ---------------------------------------------------------------------
// (d) citations of issues and planning documents

/// The citations of issue numbers or planning documents in `text`: `issue
/// 37`, `issue #`, `issues 24 and 28`, `item 5` (of an issue), `paper 00`,
/// `seeds/`. Each as (line number, line).
fn planning_citations(text: &str) -> Vec<(usize, String)> {
    let hit = |line: &str| {
        let l = line.to_lowercase();
        let after = |word: &str| {
            l.match_indices(word).any(|(k, _)| {
                let before_ok = k == 0 || !l.as_bytes()[k - 1].is_ascii_alphanumeric();
                let rest = l[k + word.len()..].trim_start_matches('s').trim_start();
                before_ok
                    && (rest.starts_with('#') || rest.starts_with(|c: char| c.is_ascii_digit()))
            })
        };
        let paper = l.match_indices("paper ").any(|(k, _)| {
            let d: String = l[k + 6..]
                .chars()
                .take_while(char::is_ascii_digit)
                .collect();
            d.len() == 2
        });
        after("issue") || after("item") || paper || l.contains("seeds/")
    };
    text.lines()
        .enumerate()
        .filter(|(_, l)| hit(l))
        .map(|(k, l)| (k + 1, l.to_string()))
        .collect()
}

#[test]
fn code_and_docs_cite_no_issue_or_planning_document() {
    let mut files = files_under("src", &[".rs", ".md"]);
    files.extend(files_under("docs", &[".md"]));
    files.extend(files_under("python/src", &[".rs"]));
    files.extend(files_under("python/asperity", &[".py", ".pyi"]));
    files.extend(["README.md".to_string(), "python/README.md".to_string()]);
    // The tests, tools, benches and examples too (this file quotes
    // citations on purpose, below).
    for (dir, exts) in [
        ("tests", &[".rs", ".py", ".sh"][..]),
        ("tools", &[".rs", ".py", ".md", ".sh"][..]),
        ("benches", &[".rs", ".py"][..]),
        ("examples", &[".rs"][..]),
        ("python/tests", &[".py"][..]),
    ] {
        files.extend(
            files_under(dir, exts)
                .into_iter()
                .filter(|f| f != "tests/it/docs.rs"),
        );
    }
    let mut found = Vec::new();
    for f in &files {
        for (n, line) in planning_citations(&read(f)) {
            found.push(format!("{f}:{n}: {}", line.trim()));
        }
    }
    assert!(
        found.is_empty(),
        "say what a thing is, not which issue or plan asked for it:\n{}",
        found.join("\n")
    );
}

#[test]
fn citations_are_recognised() {
    for cited in [
        "## Limits (issue 24)",
        "as Issue #7 asked",
        "issues 24 and 28",
        "the calibrated-law item 6",
        "see paper 00",
        "from seeds/plan.md",
    ] {
        assert_eq!(planning_citations(cited).len(), 1, "{cited}");
    }
    for plain in [
        "the issue is the tail",
        "a list item",
        "Kesari & Lew paper 2011",
        "tissue 3",
        "items: 3",
    ] {
        assert!(planning_citations(plain).is_empty(), "{plain}");
    }
}
