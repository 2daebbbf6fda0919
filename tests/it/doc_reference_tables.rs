//! The reference tables of README.md and `docs/` (lists of commands,
//! flags, scenes, formats, keys, modules, laws, constants) against their
//! source of truth: `asperity --help`, `asperity schema`, the format list of
//! `src/topography/`, the validity constants, the files on disk, the Python
//! stubs. The result tables are checked by `readme_tables.rs`,
//! `docs_tables.rs` and `challenge.rs`; `performance_tables.rs` checks the
//! timing tables' provenance.

use crate::common::cli::run;
use crate::common::markdown_table as table;
use asperity::topography::Format;
use std::path::PathBuf;

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

fn read(rel: &str) -> String {
    std::fs::read_to_string(root().join(rel)).unwrap_or_else(|e| panic!("{rel}: {e}"))
}

/// The `` `...` `` spans of a cell.
fn spans(cell: &str) -> Vec<&str> {
    cell.split('`').skip(1).step_by(2).collect()
}

/// The extensions (`.x3p`, `.001`-`.999` as `.001`) named in `text`.
fn extensions(text: &str) -> Vec<String> {
    let mut out = Vec::new();
    for span in spans(text) {
        for part in span.split(['/', '-']) {
            if let Some(ext) = part.strip_prefix('.') {
                if !ext.is_empty() && ext.chars().all(|c| c.is_ascii_alphanumeric()) {
                    out.push(ext.to_string());
                }
            }
        }
    }
    out
}

fn help(args: &[&str]) -> String {
    let (code, out, err) = run(args, &root());
    assert_eq!(code, 0, "{args:?}: {err}");
    out
}

/// README's "Command line" table: every subcommand is one `asperity
/// --help` lists, every flag one its `--help` lists, every extension one
/// the readers know, every example one `Cargo.toml` registers.
#[test]
fn the_command_table_names_real_commands_flags_and_formats() {
    let readme = read("README.md");
    let top = help(&["--help"]);
    let manifest = read("Cargo.toml");
    let mut checked = 0;
    for row in table(&readme, "| question | command |") {
        for span in spans(&row[1]) {
            let words: Vec<&str> = span.split_whitespace().collect();
            match words.as_slice() {
                ["asperity", sub, rest @ ..] => {
                    assert!(
                        top.contains(&format!("\n  {sub} ")),
                        "README: `asperity {sub}` is not a command of `asperity --help`"
                    );
                    let sub_help = help(&[sub, "--help"]);
                    for flag in rest.iter().filter(|w| w.starts_with("--")) {
                        assert!(
                            sub_help.contains(flag),
                            "README: `asperity {sub} {flag}`: no {flag} in its --help"
                        );
                    }
                    checked += 1;
                }
                ["cargo", "run", "--release", "--example", name, ..] => {
                    assert!(
                        manifest.contains(&format!("[[example]]\nname = \"{name}\"")),
                        "README: no example {name} in Cargo.toml"
                    );
                    checked += 1;
                }
                _ => {}
            }
        }
        for ext in extensions(&row[1]) {
            assert!(
                Format::from_extension(&ext).is_some(),
                "README: .{ext} is not a format the readers know"
            );
        }
    }
    assert!(checked >= 18, "{checked} commands checked");
}

/// README's scene table: every scene it lists exists (`readme_lines.rs`
/// checks the converse).
#[test]
fn the_scene_table_lists_existing_scenes() {
    for row in table(&read("README.md"), "| example scene | shows |") {
        let name = row[0].trim_matches('`');
        assert!(
            root().join("examples/scenes").join(name).exists(),
            "README: {name} is not in examples/scenes/"
        );
    }
}

/// README's validity diagnostics: the warning thresholds are the
/// constants `src/gw/validity.rs` applies.
#[test]
fn the_diagnostics_table_quotes_the_validity_constants() {
    use asperity::gw::validity::{
        AREA_FRACTION_WARN, CONTACT_RADIUS_WARN, ETA_R_SIGMA_WARN, MIN_POINTS_IN_RANGE,
    };
    let rows = table(
        &read("README.md"),
        "| diagnostic | warning | error (exit 2, naming the field) |",
    );
    let warn: Vec<&str> = rows.iter().map(|r| r[1].as_str()).collect();
    let expect = [
        format!("> {AREA_FRACTION_WARN} "),
        format!("> {CONTACT_RADIUS_WARN}"),
        format!("> {ETA_R_SIGMA_WARN}"),
        format!("< {MIN_POINTS_IN_RANGE} "),
    ];
    for (cell, want) in warn.iter().zip(&expect) {
        let cell = format!("{cell} ");
        assert!(
            cell.contains(want.as_str()),
            "README diagnostics: {cell:?} should say {want:?}"
        );
    }
    assert_eq!(rows.len(), 5, "the diagnostics table's rows changed");
}

/// The format tables of README.md, docs/surface.md and python/README.md:
/// every extension is one `Format::from_extension` reads; docs/surface.md
/// has a row for every instrument format (all but `.npy` and text), in
/// `Format::ALL`'s order, and every file it was checked against is in
/// `tests/data/topography/`.
#[test]
fn the_format_tables_are_the_formats_the_readers_know() {
    let readme_rows = table(&read("README.md"), "| family | formats | extensions |");
    let mut readme_exts = Vec::new();
    for row in &readme_rows {
        readme_exts.extend(extensions(&row[2]));
    }
    let surface = read("docs/surface.md");
    let rows = table(
        &surface,
        "| format | extensions | source of truth followed | checked against |",
    );
    let python = read("python/README.md");
    let python_row = table(&python, "| function | what | returns |")
        .into_iter()
        .find(|r| r[0].starts_with("`read_topography("))
        .expect("python/README.md: the read_topography row");
    let mut all = readme_exts.clone();
    for row in &rows {
        all.extend(extensions(&row[1]));
    }
    all.extend(extensions(&python_row[1]));
    for ext in &all {
        assert!(
            Format::from_extension(ext).is_some(),
            ".{ext} is listed but no reader knows it"
        );
    }
    // Every format in README's table, by each of its extensions.
    for f in Format::ALL {
        assert!(
            readme_exts
                .iter()
                .any(|e| Format::from_extension(e) == Some(f)),
            "README's format table has no extension of {}",
            f.describe()
        );
    }
    // docs/surface.md: one row per instrument format, in Format::ALL's order.
    let listed: Vec<Format> = rows
        .iter()
        .map(|r| {
            let exts = extensions(&r[1]);
            Format::from_extension(&exts[0]).unwrap()
        })
        .collect();
    let instruments: Vec<Format> = Format::ALL
        .into_iter()
        .filter(|f| !matches!(f, Format::Npy | Format::Text))
        .collect();
    assert_eq!(listed, instruments, "docs/surface.md's format rows");
    // Every file the readers were checked against is stored (the files
    // named before a parenthesis: the one after explains an absent file).
    let dir = root().join("tests/data/topography");
    for row in &rows {
        let named = row[3].split(" (").next().unwrap();
        for span in spans(named) {
            let names: Vec<String> = match span.split_once('{') {
                Some((head, rest)) => {
                    let (alts, tail) = rest.split_once('}').unwrap();
                    alts.split(',')
                        .map(|a| format!("{head}{a}{tail}"))
                        .collect()
                }
                None => vec![span.to_string()],
            };
            for name in names {
                if name.contains('.') && !name.contains(' ') {
                    assert!(
                        dir.join(&name).exists(),
                        "docs/surface.md: {name} is not in tests/data/topography/"
                    );
                }
            }
        }
    }
}

/// One key's line of `asperity schema`: its default column.
fn schema_default(schema: &str, key: &str) -> Option<String> {
    let line = schema
        .lines()
        .find(|l| l.split_whitespace().next() == Some(key))?;
    let at = line.find(" default ")?;
    let rest = line[at + " default ".len()..].trim_start();
    // the default is one token ("m" with its quotes, 1, false, -)
    Some(rest.split_whitespace().next()?.to_string())
}

/// docs/surface.md's scene keys of a measured map: every key is a
/// `surface.` key of `asperity schema`, with the default it states where
/// the schema has one.
#[test]
fn the_measured_map_keys_are_scene_keys_with_their_defaults() {
    let schema = help(&["schema"]);
    for row in table(&read("docs/surface.md"), "| key | meaning | default |") {
        let key = format!("surface.{}", row[0].trim_matches('`'));
        let default = schema_default(&schema, &key)
            .unwrap_or_else(|| panic!("docs/surface.md: {key} is not in `asperity schema`"));
        if default != "-" {
            assert_eq!(
                row[2].trim_matches('`'),
                default,
                "docs/surface.md: the default of {key}"
            );
        }
    }
}

/// docs/physics.md's laws and what they keep: every law is one `asperity
/// law --law` or `law.kind` accepts; the sphere's table names scene keys
/// that exist.
#[test]
fn the_physics_tables_name_real_laws_and_keys() {
    let physics = read("docs/physics.md");
    let schema = help(&["schema"]);
    let law_help = help(&["law", "--help"]);
    let kinds = schema
        .lines()
        .find(|l| l.starts_with("law.kind "))
        .expect("law.kind in the schema")
        .to_string();
    for row in table(&physics, "| law | what it keeps | what it neglects |") {
        let name = match row[0].as_str() {
            "Maugis–Dugdale" => "maugis".to_string(),
            other => other.to_lowercase(),
        };
        assert!(
            law_help.contains(&format!(" {name},"))
                || law_help.contains(&format!(" {name}\n"))
                || kinds.contains(&format!("|{name}|")),
            "docs/physics.md: law {} is neither an `asperity law` nor a law.kind",
            row[0]
        );
    }
    let sphere_rows = table(&physics, "| flat assumption | with `[sphere]` |");
    let mut keys = 0;
    for row in &sphere_rows {
        for span in spans(&row[0]) {
            let key = span.trim_matches(['[', ']']);
            if key.starts_with("surface.") || span.starts_with('[') {
                assert!(
                    schema
                        .lines()
                        .any(|l| l.split_whitespace().next() == Some(key)),
                    "docs/physics.md: {span} is not in `asperity schema`"
                );
                keys += 1;
            }
        }
    }
    assert!(keys >= 3, "{keys} keys checked");
}

/// docs/architecture.md's module tables: every module or file exists
/// (under `src/` for the core, `src/study/` for the study layer); the
/// distribution table lists the scene's distributions.
#[test]
fn the_architecture_tables_name_existing_modules() {
    let arch = read("docs/architecture.md");
    let at = arch.find("## Study layer").unwrap();
    let (core, study) = arch.split_at(at);
    for (md, dir) in [(core, "src"), (study, "src/study")] {
        for row in table(md, "| module | concept |") {
            let name = row[0].trim_matches('`');
            assert!(
                root().join(dir).join(name).exists(),
                "docs/architecture.md: {dir}/{name} does not exist"
            );
        }
    }
    for row in table(&arch, "| layer | where | depends on | builds with |") {
        for span in spans(&row[1]) {
            if span.starts_with("src/") || span.starts_with("python/") {
                assert!(
                    root().join(span).exists(),
                    "docs/architecture.md: {span} does not exist"
                );
            }
        }
    }
    let schema = help(&["schema"]);
    let dists = schema
        .lines()
        .find(|l| l.starts_with("surface.distribution "))
        .unwrap()
        .to_string();
    let names: Vec<String> = table(&arch, "| name | `sigma` means |")
        .iter()
        .map(|r| spans(&r[0])[0].to_string())
        .collect();
    let listed = dists
        .split("one of ")
        .nth(1)
        .unwrap()
        .split_whitespace()
        .next()
        .unwrap();
    assert_eq!(
        names.join("|"),
        listed,
        "docs/architecture.md's distributions against surface.distribution"
    );
}

/// The unsigned numbers written in `text` (`q^-3.6` gives 3.6).
fn numbers(text: &str) -> Vec<f64> {
    let mut out = Vec::new();
    let mut cur = String::new();
    for c in text.chars().chain([' ']) {
        if c.is_ascii_digit() || (c == '.' && !cur.is_empty()) {
            cur.push(c);
        } else {
            if let Ok(x) = cur.trim_end_matches('.').parse::<f64>() {
                out.push(x);
            }
            cur.clear();
        }
    }
    out
}

/// examples/challenge/README.md's problem: the constants of
/// `src/bem/challenge.rs`, each value in its row (in the row's unit).
#[test]
fn the_challenge_problem_table_is_the_code_s() {
    use asperity::bem::challenge::{self as ch, Challenge};
    let rows = table(&read("examples/challenge/README.md"), "| | |");
    let c = Challenge::at(512).unwrap();
    let expect: [(&str, Vec<f64>); 8] = [
        (
            "surface",
            vec![
                ch::HURST,
                ch::SIDE * 1e3,
                ch::ROLL_OFF_WAVELENGTH * 1e6,
                2.0 * (1.0 + ch::HURST),
                ch::SHORT_WAVELENGTH * 1e6,
            ],
        ),
        (
            "generated",
            vec![ch::SEED as f64, ch::SIDE * 1e3, ch::SLOPE_RMS],
        ),
        ("material", vec![c.contact_modulus / 1e6]),
        (
            "reference pressure",
            vec![
                c.reference_pressure / (c.contact_modulus * ch::SLOPE_RMS),
                c.reference_pressure / 1e3,
            ],
        ),
        ("interaction", vec![c.adhesion_energy * 1e3]),
        (
            "range",
            vec![
                ch::RANGE_FACTOR,
                ch::PUBLISHED_RANGE * 1e9,
                c.adhesion_range() * 1e9,
            ],
        ),
        ("non-adhesive", vec![c.reference_pressure / 1e3]),
        ("adhesive", vec![]),
    ];
    for (name, values) in expect {
        let row = rows
            .iter()
            .find(|r| r[0] == name)
            .unwrap_or_else(|| panic!("examples/challenge/README.md: no row {name:?}"));
        let written = numbers(&row[1]);
        for v in values {
            assert!(
                written.iter().any(|w| (w - v).abs() <= 1e-9 * v.abs()),
                "examples/challenge/README.md, {name}: {v} is not in {:?}",
                row[1]
            );
        }
    }
    assert_eq!(rows.len(), 8, "the problem table's rows changed");
}

/// The parameter names of `def NAME(...)` in the Python stubs.
fn stub_parameters(stubs: &str, name: &str) -> Option<Vec<String>> {
    let at = stubs.find(&format!("\ndef {name}("))?;
    let rest = &stubs[at + name.len() + 6..];
    let end = rest.find(") ->")?;
    Some(
        rest[..end]
            .split(',')
            .map(|p| {
                p.split([':', '='])
                    .next()
                    .unwrap()
                    .trim()
                    .trim_start_matches('*')
                    .to_string()
            })
            .filter(|p| !p.is_empty())
            .collect(),
    )
}

/// python/README.md's function table: every function is in the package's
/// stubs (`python/asperity/__init__.pyi`, which `stubtest` checks against
/// the module), with the parameters the table shows in that order.
#[test]
fn the_python_function_table_is_the_package_s() {
    let stubs = read("python/asperity/__init__.pyi");
    let mut checked = 0;
    for row in table(&read("python/README.md"), "| function | what | returns |") {
        for span in spans(&row[0]) {
            let (name, params) = match span.split_once('(') {
                Some((name, rest)) => {
                    let ps: Vec<String> = rest
                        .trim_end_matches(')')
                        .split(',')
                        .map(|p| p.split('=').next().unwrap().trim().to_string())
                        .filter(|p| !p.is_empty() && p != "*" && p != "...")
                        .collect();
                    (name, ps)
                }
                None => (span, Vec::new()),
            };
            let have = stub_parameters(&stubs, name)
                .unwrap_or_else(|| panic!("python/README.md: no def {name} in the stubs"));
            let shown: Vec<&String> = have.iter().filter(|p| params.contains(p)).collect();
            assert_eq!(
                shown.iter().map(|s| s.as_str()).collect::<Vec<_>>(),
                params.iter().map(String::as_str).collect::<Vec<_>>(),
                "python/README.md: {name}'s parameters against its stub {have:?}"
            );
            checked += 1;
        }
    }
    assert!(checked >= 18, "{checked} functions checked");
}
