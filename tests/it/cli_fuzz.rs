//! CLI fuzz: every subcommand of `asperity --help`
//! with each numeric flag set to 0, -1, NaN, +-inf, 1e300, 1e-300, a huge
//! count and text, and every file argument given an empty file, binary
//! garbage, a truncated or wrong-dtype `.npy`, a CSV with text, a CSV with a
//! byte-order mark, a directory and a missing path. Every case runs the
//! built binary under a time limit and must
//! - not panic, abort or hang (a killed or timed-out process fails);
//! - exit 2 naming the flag (or file) it was given, or
//! - exit 0 with output as finite as the unmutated command's (`--json`
//!   stdout parses and has no more nulls than the base command's).
//!
//! Exit 1 (a computation failure) on user input fails too. All failures are
//! listed together. About 1,000 processes, a few seconds of CPU in the
//! test profile; cases run on two threads.
use crate::common::cli;
use cli::{bin, run_within, tmp, Outcome};
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Mutex;

/// Seconds one process may take before it counts as a hang.
const LIMIT_S: f64 = 30.0;

/// Values every numeric flag is set to.
const VALUES: [&str; 10] = [
    "0", "-1", "nan", "inf", "-inf", "1e300", "1e-300", "1e20", "abc", "",
];

/// One command line, and what an exit 2 must name.
struct Case {
    args: Vec<String>,
    names: Vec<String>,
    /// The unmutated command's null count in its `--json` output (`None`:
    /// no JSON check).
    base_nulls: Option<usize>,
}

fn data(name: &str) -> String {
    format!("{}/examples/data/{name}", env!("CARGO_MANIFEST_DIR"))
}

fn scene(name: &str) -> String {
    format!("{}/examples/scenes/{name}", env!("CARGO_MANIFEST_DIR"))
}

fn strings(v: &[&str]) -> Vec<String> {
    v.iter().map(|s| s.to_string()).collect()
}

/// `base` with `flag`'s value set to `value`, written `--flag=value` (so
/// `-1` and `-inf` are values, not flags), appended when absent.
fn with_flag(base: &[String], flag: &str, value: &str) -> Vec<String> {
    let mut v = base.to_vec();
    let joined = format!("{flag}={value}");
    match v.iter().position(|a| a == flag) {
        Some(i) => {
            v[i] = joined;
            v.remove(i + 1);
        }
        None => v.push(joined),
    }
    v
}

/// The number of nulls in a JSON text (`None` when it does not parse).
fn nulls(text: &str) -> Option<usize> {
    fn count(v: &serde_json::Value) -> usize {
        match v {
            serde_json::Value::Null => 1,
            serde_json::Value::Array(a) => a.iter().map(count).sum(),
            serde_json::Value::Object(o) => o.values().map(count).sum(),
            _ => 0,
        }
    }
    serde_json::from_str::<serde_json::Value>(text)
        .ok()
        .map(|v| count(&v))
}

fn run_args(args: &[String], dir: &Path) -> Outcome {
    let mut cmd = bin();
    cmd.args(args)
        .current_dir(dir)
        .env("ASPERITY_CACHE", dir.join("cache"))
        .env("ASPERITY_PROGRESS_AFTER", "1000");
    run_within(cmd, LIMIT_S)
}

/// The subcommands (base command lines, cheap and valid) and their numeric
/// flags.
fn commands() -> Vec<(Vec<String>, Vec<&'static str>)> {
    let punch = strings(&[
        "punch",
        "--estar",
        "1e9",
        "--w",
        "0.05",
        "--radius",
        "1e-4",
        "--amplitude",
        "0.5",
        "--wavelength",
        "1e-5",
        "--json",
    ]);
    vec![
        (
            strings(&["law", "--law", "maugis", "--lambda", "1", "--json"]),
            vec!["--lambda", "--law"],
        ),
        (
            strings(&[
                "fn", "--dist", "gaussian", "--n", "1", "--h", "-1,0,1", "--json",
            ]),
            vec!["--n", "--h", "--dist"],
        ),
        (
            strings(&["sphere", "--mu", "1", "--json"]),
            vec!["--mu", "--rho", "--resolution"],
        ),
        (
            strings(&["rough-sphere", "--mu", "1", "--d", "0,1", "--json"]),
            vec!["--mu", "--d", "--rho", "--tolerance"],
        ),
        (
            punch.clone(),
            vec![
                "--estar",
                "--w",
                "--radius",
                "--amplitude",
                "--wavelength",
                "--radii",
                "--depths",
            ],
        ),
        (with_flag(&punch, "--cycle", "0:1e-6"), vec!["--cycle"]),
        (
            strings(&[
                "punch-fit",
                &data("punch-gelatin.csv"),
                "--radius",
                "0.25",
                "--json",
            ]),
            vec!["--radius"],
        ),
        (
            strings(&[
                "surface",
                &data("selfaffine-64-nm.txt"),
                "--pixel-size",
                "1.5625e-6",
                "--scale",
                "1e-9",
                "--estar",
                "1e11",
                "--hardness",
                "2e9",
                "--json",
            ]),
            vec!["--pixel-size", "--scale", "--estar", "--hardness"],
        ),
        (
            strings(&[
                "spots",
                &data("spots.csv"),
                "--resistivity",
                "2.44e-8",
                "--json",
            ]),
            vec!["--resistivity", "--mean-free-path"],
        ),
        (
            strings(&["heating", "--voltage", "0.1", "--json"]),
            vec![
                "--voltage",
                "--bulk-temperature",
                "--softening-temperature",
                "--melting-temperature",
            ],
        ),
        (
            strings(&["heating", "--max-temperature", "400", "--json"]),
            vec!["--max-temperature"],
        ),
        (
            strings(&[
                "shape",
                "--profile",
                "paraboloid",
                "--radius",
                "1e-6",
                "--estar",
                "1e9",
                "--w",
                "0.05",
                "--json",
            ]),
            vec![
                "--radius",
                "--estar",
                "--w",
                "--radii",
                "--stress",
                "--profile",
            ],
        ),
        (
            strings(&[
                "shape",
                "--profile",
                "cone",
                "--tan-angle",
                "0.3",
                "--estar",
                "1e9",
                "--w",
                "0.05",
                "--json",
            ]),
            vec!["--tan-angle"],
        ),
        (
            strings(&[
                "shape",
                "--profile",
                "power",
                "--exponent",
                "4",
                "--coefficient",
                "1e15",
                "--estar",
                "1e9",
                "--w",
                "0.05",
                "--json",
            ]),
            vec!["--exponent", "--coefficient"],
        ),
        (
            strings(&[
                "persson",
                "--hurst",
                "0.8",
                "--q-long",
                "1e5",
                "--q-roll",
                "1e5",
                "--q-short",
                "1e8",
                "--h-rms",
                "1e-9",
                "--estar",
                "1e9",
                "--pressures",
                "1e6",
                "--adhesion-energy",
                "0.05",
                "--json",
            ]),
            vec![
                "--hurst",
                "--q-long",
                "--q-roll",
                "--q-short",
                "--h-rms",
                "--estar",
                "--pressures",
                "--gamma",
                "--adhesion-energy",
            ],
        ),
        (
            strings(&[
                "persson",
                "--hurst",
                "0.8",
                "--q-long",
                "1e5",
                "--q-roll",
                "1e5",
                "--q-short",
                "1e8",
                "--slope-rms",
                "0.1",
                "--estar",
                "1e9",
                "--pressures",
                "1e6",
                "--json",
            ]),
            vec!["--slope-rms"],
        ),
        (
            strings(&[
                "bem",
                &data("selfaffine-64-nm.txt"),
                "--scale",
                "1e-9",
                "--pixel-size",
                "1e-7",
                "--estar",
                "1e9",
                "--pressures",
                "1e6",
                "--resistivity",
                "2.44e-8",
                "--json",
            ]),
            vec![
                "--scale",
                "--pixel-size",
                "--estar",
                "--pressures",
                "--resistivity",
                "--gamma",
                "--tolerance",
                "--max-iterations",
                "--memory-limit-mib",
            ],
        ),
        (
            strings(&[
                "bem",
                &data("selfaffine-64-nm.txt"),
                "--scale",
                "1e-9",
                "--pixel-size",
                "1e-7",
                "--estar",
                "1e9",
                "--gaps",
                "2e-7",
                "--adhesion-energy",
                "0.01",
                "--adhesion-range",
                "1e-8",
                "--periodic",
                "--json",
            ]),
            vec!["--gaps", "--adhesion-energy", "--adhesion-range"],
        ),
        (
            strings(&["map", "--tolerance", "0.05", "--out", "map-out"]),
            vec!["--tolerance"],
        ),
        (
            strings(&[
                "sweep",
                &scene("soft-jkr.toml"),
                "--vary",
                "surface.sigma=2e-9:3e-9:2",
                "--threads",
                "1",
                "--out",
                "sweep-out",
            ]),
            vec!["--samples", "--seed", "--threads", "--shard"],
        ),
    ]
}

/// `--vary` specifications that are wrong in one part each.
const BAD_VARY: [&str; 12] = [
    "surface.sigma=nan:3e-9:2",
    "surface.sigma=2e-9:inf:2",
    "surface.sigma=2e-9:3e-9:0",
    "surface.sigma=2e-9:3e-9:-1",
    "surface.sigma=2e-9:3e-9:1e20",
    "surface.sigma=2e-9:3e-9:100000000000",
    "surface.sigma=-1:3e-9:2",
    "surface.sigma=1e300:1e301:2",
    "surface.sigm=2e-9:3e-9:2",
    "montecarlo.summits=1:100:3",
    "surface.sigma",
    "",
];

/// Bad files, written into `dir`: (name, bytes); plus a directory and a
/// missing path.
fn bad_files(dir: &Path) -> Vec<PathBuf> {
    let mut npy_f4 = b"\x93NUMPY\x01\x00".to_vec();
    let header = "{'descr': '<f4', 'fortran_order': False, 'shape': (4, 4), }";
    let mut h = header.to_string();
    while !(10 + h.len() + 1).is_multiple_of(64) {
        h.push(' ');
    }
    h.push('\n');
    npy_f4.extend_from_slice(&(h.len() as u16).to_le_bytes());
    npy_f4.extend_from_slice(h.as_bytes());
    npy_f4.extend(std::iter::repeat_n(0u8, 64));
    let truncated = {
        let full = std::fs::read(data("measured-topography.npy")).unwrap();
        full[..full.len() / 2].to_vec()
    };
    let header_only = {
        let full = std::fs::read(data("measured-topography.npy")).unwrap();
        full[..40.min(full.len())].to_vec()
    };
    let garbage: Vec<u8> = (0..4096u32)
        .map(|i| (i.wrapping_mul(2_654_435_761) >> 13) as u8)
        .collect();
    let files: Vec<(&str, Vec<u8>)> = vec![
        ("empty.csv", vec![]),
        ("empty.npy", vec![]),
        ("empty.toml", vec![]),
        ("garbage.csv", garbage.clone()),
        ("garbage.npy", garbage.clone()),
        ("garbage.toml", garbage.clone()),
        ("garbage.txt", garbage),
        ("truncated.npy", truncated),
        ("header-only.npy", header_only),
        ("f4.npy", npy_f4),
        ("text.csv", b"x_m,y_m,radius_m\n1,2,three\n".to_vec()),
        ("text.txt", b"1 2 3\n4 five 6\n7 8 9\n".to_vec()),
        (
            "bom.csv",
            b"\xef\xbb\xbfx_m,y_m,radius_m\n0,0,1e-6\n1e-4,0,2e-6\n".to_vec(),
        ),
        ("ragged.txt", b"1 2 3\n4 5\n6 7 8\n".to_vec()),
        ("nan.txt", b"1 2 3\n4 nan 6\n7 8 9\n".to_vec()),
        ("one.txt", b"1\n".to_vec()),
        ("header.csv", b"phase,radius_m,load_N\n".to_vec()),
        (
            "fit-text.csv",
            b"phase,radius_m,load_N\nloading,1e-3,abc\n".to_vec(),
        ),
    ];
    let mut paths: Vec<PathBuf> = files
        .into_iter()
        .map(|(name, bytes)| {
            let p = dir.join(name);
            std::fs::write(&p, bytes).unwrap();
            p
        })
        .collect();
    let sub = dir.join("a-directory.csv");
    std::fs::create_dir_all(&sub).unwrap();
    paths.push(sub);
    paths.push(dir.join("missing.npy"));
    paths
}

/// Every case: numeric flags of every subcommand, bad `--vary`, bad files.
fn cases(dir: &Path) -> Vec<Case> {
    let mut out = Vec::new();
    for (base, flags) in commands() {
        let o = run_args(&base, dir);
        assert_eq!(o.code, Some(0), "base {base:?}: {}", o.stderr);
        let base_nulls = if base.iter().any(|a| a == "--json") {
            Some(nulls(&o.stdout).unwrap_or_else(|| panic!("base {base:?}: {}", o.stdout)))
        } else {
            None
        };
        for flag in flags {
            for value in VALUES {
                out.push(Case {
                    args: with_flag(&base, flag, value),
                    names: vec![flag.to_string()],
                    base_nulls,
                });
            }
        }
    }
    let sweep = commands()
        .into_iter()
        .find(|(b, _)| b[0] == "sweep")
        .unwrap()
        .0;
    for v in BAD_VARY {
        // The path the user wrote names the problem as well as --vary.
        let path = v.split('=').next().unwrap_or("").to_string();
        out.push(Case {
            args: with_flag(&sweep, "--vary", v),
            names: vec!["--vary".into(), path],
            base_nulls: None,
        });
    }
    let files = bad_files(dir);
    for f in &files {
        let path = f.to_string_lossy().into_owned();
        let name = f.file_name().unwrap().to_string_lossy().into_owned();
        let names = vec![path.clone(), name];
        let lines: Vec<Vec<String>> = vec![
            strings(&["run", &path, "--out", "run-out"]),
            strings(&["run", &path, "--plan"]),
            strings(&[
                "sweep",
                &path,
                "--vary",
                "surface.sigma=2e-9:3e-9:2",
                "--out",
                "sweep-bad",
            ]),
            strings(&["surface", &path, "--pixel-size", "1e-7", "--json"]),
            strings(&[
                "bem",
                &path,
                "--pixel-size",
                "1e-7",
                "--estar",
                "1e9",
                "--pressures",
                "1e6",
                "--json",
            ]),
            strings(&["spots", &path, "--resistivity", "2.44e-8", "--json"]),
            strings(&["punch-fit", &path, "--radius", "0.25", "--json"]),
            strings(&["merge", &path, "--out", "merged"]),
        ];
        // (Outputs that cannot be written exit 1 by design, naming the
        // path: tests/it/cli_robustness.rs.)
        for args in lines {
            out.push(Case {
                args,
                names: names.clone(),
                base_nulls: None,
            });
        }
    }
    out
}

/// Whether the JSON's warnings say which values are null.
fn explained_nulls(text: &str) -> bool {
    serde_json::from_str::<serde_json::Value>(text)
        .ok()
        .and_then(|v| v.get("warnings").cloned())
        .and_then(|w| w.as_array().cloned())
        .is_some_and(|w| {
            w.iter()
                .any(|x| x.as_str().is_some_and(|s| s.contains("null")))
        })
}

/// What is wrong with one outcome, if anything.
fn judge(case: &Case, o: &Outcome) -> Option<String> {
    if o.timed_out {
        return Some(format!("hang (> {LIMIT_S} s)"));
    }
    if o.stderr.contains("panicked") || o.stderr.contains("RUST_BACKTRACE") {
        return Some(format!("panic: {}", o.stderr.trim()));
    }
    match o.code {
        Some(0) => {
            let json = case.args.iter().any(|a| a == "--json");
            if let (true, Some(base)) = (json, case.base_nulls) {
                match nulls(&o.stdout) {
                    None => return Some(format!("exit 0, stdout not JSON: {}", o.stdout)),
                    // Holm's relation gives no temperature once molten
                    // (a melted contact): that null is the answer.
                    // Nulls a warning explains are answers too.
                    Some(n)
                        if n > base
                            && !o.stdout.contains("\"condition\":\"molten\"")
                            && !explained_nulls(&o.stdout) =>
                    {
                        return Some(format!(
                            "exit 0 with {n} nulls (base {base}): {}",
                            &o.stdout[..o.stdout.len().min(400)]
                        ))
                    }
                    _ => {}
                }
            }
            None
        }
        Some(2) => {
            let named = case
                .names
                .iter()
                .any(|n| !n.is_empty() && o.stderr.contains(n.as_str()));
            (!named).then(|| {
                format!(
                    "exit 2 without naming {:?}: {}",
                    case.names,
                    o.stderr.trim()
                )
            })
        }
        Some(c) => Some(format!("exit {c}: {}", o.stderr.trim())),
        None => Some(format!("killed by a signal: {}", o.stderr.trim())),
    }
}

#[test]
fn every_subcommand_survives_bad_numbers_and_bad_files() {
    let t0 = std::time::Instant::now();
    let dir = tmp("all");
    let cases = cases(&dir);
    let next = AtomicUsize::new(0);
    let failures = Mutex::new(Vec::new());
    std::thread::scope(|s| {
        for _ in 0..2 {
            s.spawn(|| loop {
                let i = next.fetch_add(1, Ordering::Relaxed);
                let Some(case) = cases.get(i) else { break };
                // Each case in its own directory: outputs do not collide.
                let d = dir.join(format!("case-{i}"));
                std::fs::create_dir_all(&d).unwrap();
                let o = run_args(&case.args, &d);
                if let Some(why) = judge(case, &o) {
                    failures
                        .lock()
                        .unwrap()
                        .push(format!("asperity {}\n    {why}", shell(&case.args)));
                }
                let _ = std::fs::remove_dir_all(&d);
            });
        }
    });
    let failures = failures.into_inner().unwrap();
    eprintln!(
        "{} cases in {:.1} s (wall), {} failures",
        cases.len(),
        t0.elapsed().as_secs_f64(),
        failures.len()
    );
    assert!(
        failures.is_empty(),
        "{} of {} cases failed:\n{}",
        failures.len(),
        cases.len(),
        failures.join("\n")
    );
}

/// A command line as a shell would show it.
fn shell(args: &[String]) -> String {
    args.iter()
        .map(|a| {
            if a.is_empty() || a.contains([' ', ',', '\'']) {
                format!("'{a}'")
            } else {
                a.clone()
            }
        })
        .collect::<Vec<_>>()
        .join(" ")
}
