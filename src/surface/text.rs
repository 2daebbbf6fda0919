//! Text height matrices (`.txt`, `.csv`, `.asc`): one row of the map per
//! line, values separated by commas or by whitespace (spaces, tabs).
//! Blank lines and lines starting with `#` (headers such as Gwyddion's
//! ASCII export) are skipped; a trailing `\r` is ignored.

use super::map::{HeightMap, NAME};
use crate::error::{Error, Result};

/// Parses a text matrix into a height map.
///
/// # Errors
/// [`Error::Invalid`] named `topography` for an empty file, a value that is
/// not a number or an empty comma-separated field (with its line), ragged
/// rows (the first line whose count differs), or any reason
/// [`HeightMap::new`] gives (1-D, too small, NaN or infinite heights).
pub fn parse(text: &str) -> Result<HeightMap> {
    // A UTF-8 byte-order mark (spreadsheets write one) is no height.
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let mut heights = Vec::new();
    let mut cols = 0;
    let mut rows = 0;
    for (k, line) in text.lines().enumerate() {
        let line = line.trim();
        if line.is_empty() || line.starts_with('#') {
            continue;
        }
        let before = heights.len();
        if line.contains(',') {
            for field in line.split(',') {
                heights.push(number(field.trim(), k + 1)?);
            }
        } else {
            for field in line.split_whitespace() {
                heights.push(number(field, k + 1)?);
            }
        }
        let n = heights.len() - before;
        if rows == 0 {
            cols = n;
        } else if n != cols {
            return Err(Error::invalid(
                NAME,
                format!(
                    "ragged rows: line {} has {n} values, the first row has {cols}",
                    k + 1
                ),
            ));
        }
        rows += 1;
    }
    HeightMap::new(rows, cols, heights)
}

fn number(field: &str, line: usize) -> Result<f64> {
    if field.is_empty() {
        return Err(Error::invalid(NAME, format!("line {line}: empty field")));
    }
    field
        .parse()
        .map_err(|_| Error::invalid(NAME, format!("line {line}: '{field}' is not a number")))
}

/// A map as text: one row per line, values separated by a space, each in
/// Rust's shortest round-trip form (so [`parse`] gives back the same bits).
pub fn to_text(map: &HeightMap) -> String {
    let mut out = String::with_capacity(map.heights().len() * 24);
    for row in map.heights().chunks(map.cols()) {
        let line: Vec<String> = row.iter().map(|z| format!("{z:e}")).collect();
        out.push_str(&line.join(" "));
        out.push('\n');
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reads_whitespace_comma_and_comments_and_round_trips() {
        let a = parse("# header\n1 2 3\n4\t5  6\r\n\n7 8 9\n").unwrap();
        let b = parse("1,2,3\n4, 5 ,6\n7,8,9").unwrap();
        assert_eq!(a, b);
        assert_eq!((a.rows(), a.cols()), (3, 3));
        assert_eq!(a.heights()[5], 6.0);
        let z: Vec<f64> = (0..20).map(|k| (k as f64 * 0.37).sin() * 1e-9).collect();
        let m = HeightMap::new(4, 5, z).unwrap();
        assert_eq!(parse(&to_text(&m)).unwrap(), m);
    }

    #[test]
    fn rejects_each_bad_file_with_its_reason() {
        let err = |t: &str| parse(t).unwrap_err().to_string();
        assert!(err("").contains("empty"));
        assert!(err("# only a header\n\n").contains("empty"));
        assert!(err("1 2 3 4\n").contains("1-D"));
        assert!(err("1\n2\n3\n").contains("1-D"));
        assert!(err("1 2 3\n4 5\n7 8 9\n").contains("ragged rows: line 2 has 2 values"));
        assert!(err("1 2 3\n4 x 6\n7 8 9\n").contains("line 2: 'x' is not a number"));
        assert!(err("1,2,3\n4,,6\n7,8,9\n").contains("line 2: empty field"));
        assert!(err("1 2 3\n4 nan 6\n7 8 9\n").contains("NaN height at row 1, column 1"));
        assert!(err("1 2 3\n4 5 6\n7 8 -inf\n").contains("infinite height at row 2"));
    }
}
