//! The scene's long number lists read without the TOML parser:
//! `[program] separations` and `loads`, a thousand numbers each at most,
//! cost the `toml` crate about a microsecond a number (a token, a span, a
//! value each), a third of a 1000-state scene's reading. Such a list, on
//! lines of its own in the `[program]` table and made only of TOML floats
//! (`-5e-09`, `1.25`, `+2.0E3`: a point or an exponent, no underscores,
//! no `inf`/`nan`, no comments), is read here and blanked in the text
//! (its characters become spaces, the newlines stay: every line and column
//! of the rest is where it was); the parser then reads an empty list,
//! which the numbers replace. Anything else is left to the parser, and so
//! is the whole text when the blanked one does not parse to those empty
//! lists (its errors are then the parser's on the text as written).

/// The keys of `[program]` read here.
const KEYS: [&str; 2] = ["separations", "loads"];

/// Lists taken out of a scene's text: the blanked text and each key's
/// numbers.
pub(super) struct Taken {
    /// The text with the taken lists' numbers and commas as spaces.
    pub text: String,
    /// `(key, numbers)` for each list taken.
    pub lists: Vec<(&'static str, Vec<f64>)>,
}

/// Takes the `[program]` number lists out of `text`, or `None` when there
/// is none to take (or the text has a multi-line string, where a line is
/// not what it seems).
pub(super) fn take(text: &str) -> Option<Taken> {
    if text.contains("\"\"\"") || text.contains("'''") {
        return None;
    }
    let mut out: Option<Taken> = None;
    let mut in_program = false;
    let mut offset = 0;
    for line in text.split_inclusive('\n') {
        let start = offset;
        offset += line.len();
        let t = line.trim();
        if let Some(header) = table_header(t) {
            in_program = header == "program";
            continue;
        }
        if !in_program {
            continue;
        }
        let Some((key, after)) = KEYS.iter().find_map(|k| Some((*k, key_value(t, k)?))) else {
            continue;
        };
        if !after.starts_with('[') {
            continue;
        }
        // The list from its `[` to its `]`, possibly over several lines.
        let open = start + (line.len() - line.trim_start().len()) + (t.len() - after.len());
        let close_rel = text[open..].find(']')?;
        let close = open + close_rel;
        let Some(numbers) = floats(&text[open + 1..close]) else {
            continue;
        };
        // Nothing but a comment may follow the `]` on its line.
        let rest = text[close + 1..].split('\n').next().unwrap_or("").trim();
        if !(rest.is_empty() || rest.starts_with('#')) {
            continue;
        }
        let taken = out.get_or_insert_with(|| Taken {
            text: text.to_string(),
            lists: Vec::new(),
        });
        if taken.lists.iter().any(|(k, _)| *k == key) {
            // Twice: the parser's duplicate-key error, on the text as written.
            return None;
        }
        // The byte edit: the range holds only ASCII digits, signs,
        // points, exponents, commas and whitespace; they become spaces
        // (newlines kept), so the text stays valid UTF-8 of the same length.
        let mut bytes = std::mem::take(&mut taken.text).into_bytes();
        for b in &mut bytes[open + 1..close] {
            if *b != b'\n' && *b != b'\r' {
                *b = b' ';
            }
        }
        taken.text = String::from_utf8(bytes).ok()?;
        taken.lists.push((key, numbers));
    }
    out
}

/// The name of the table a trimmed line opens (`[program]` -> `program`,
/// also with a comment after it), or `None` if it is no table header.
fn table_header(t: &str) -> Option<&str> {
    let inner = t.strip_prefix('[')?;
    let end = inner.find(']')?;
    let rest = inner[end + 1..].trim();
    if !(rest.is_empty() || rest.starts_with('#')) {
        return None;
    }
    let name = inner[..end].trim();
    name.bytes()
        .all(|b| b.is_ascii_alphanumeric() || b == b'_' || b == b'-' || b == b'.' || b == b'[')
        .then_some(name)
}

/// What follows `key =` on a trimmed line that assigns `key`.
fn key_value<'a>(t: &'a str, key: &str) -> Option<&'a str> {
    let rest = t.strip_prefix(key)?.trim_start();
    Some(rest.strip_prefix('=')?.trim_start())
}

/// The numbers of a list's inside, if every item is a TOML float (a
/// trailing comma allowed) and there is at least one.
fn floats(inside: &str) -> Option<Vec<f64>> {
    let mut out = Vec::with_capacity(inside.len() / 8);
    let mut items = inside.split(',').peekable();
    while let Some(item) = items.next() {
        let item = item.trim_matches(|c| c == ' ' || c == '\t' || c == '\n' || c == '\r');
        if item.is_empty() && items.peek().is_none() && !out.is_empty() {
            break;
        }
        if !is_toml_float(item) {
            return None;
        }
        let x: f64 = item.parse().ok()?;
        if !x.is_finite() {
            return None;
        }
        out.push(x);
    }
    (!out.is_empty()).then_some(out)
}

/// TOML's float without underscores or special values:
/// `[+-]? (0 | [1-9][0-9]*) ('.' [0-9]+)? ([eE] [+-]? [0-9]+)?` with a
/// fraction or an exponent (an integer is the parser's to read).
fn is_toml_float(s: &str) -> bool {
    let b = s.as_bytes();
    let mut i = 0;
    if i < b.len() && (b[i] == b'+' || b[i] == b'-') {
        i += 1;
    }
    let digits = |i: &mut usize| {
        let from = *i;
        while *i < b.len() && b[*i].is_ascii_digit() {
            *i += 1;
        }
        *i - from
    };
    let int_start = i;
    let n = digits(&mut i);
    if n == 0 || (n > 1 && b[int_start] == b'0') {
        return false;
    }
    let mut float = false;
    if i < b.len() && b[i] == b'.' {
        i += 1;
        if digits(&mut i) == 0 {
            return false;
        }
        float = true;
    }
    if i < b.len() && (b[i] == b'e' || b[i] == b'E') {
        i += 1;
        if i < b.len() && (b[i] == b'+' || b[i] == b'-') {
            i += 1;
        }
        if digits(&mut i) == 0 {
            return false;
        }
        float = true;
    }
    float && i == b.len()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn toml_floats_only() {
        for ok in ["1.0", "-5e-09", "+2.0E3", "0.5", "0e0", "1e400", "12.5e+1"] {
            assert!(is_toml_float(ok), "{ok}");
        }
        for bad in [
            "1", "01.0", ".5", "5.", "1e", "1_000.0", "inf", "nan", "", "-", "1.0.0", "1e5.0",
            "0x10",
        ] {
            assert!(!is_toml_float(bad), "{bad}");
        }
        // 1e400 is a TOML float but not a finite one: the parser's to refuse.
        assert_eq!(floats("1.0, 1e400"), None);
        assert_eq!(floats("1.0, 2.0,"), Some(vec![1.0, 2.0]));
        assert_eq!(floats("1.0,, 2.0"), None);
        assert_eq!(floats(" "), None);
    }

    #[test]
    fn blanks_keep_every_line_and_column() {
        let text = "title = \"x\"\n[program]\nseparations = [1.0, -2e-9,\n  3.5] # c\npoints = 4\n";
        let t = take(text).unwrap();
        assert_eq!(t.text.len(), text.len());
        assert_eq!(t.text.lines().count(), text.lines().count());
        assert_eq!(t.lists, vec![("separations", vec![1.0, -2e-9, 3.5])]);
        assert!(t.text.contains("separations = [           \n     ] # c"));
        // Not in [program], with an integer, with a comment inside: left alone.
        assert!(take("[surface]\nseparations = [1.0]\n").is_none());
        assert!(take("[program]\nloads = [1, 2.0]\n").is_none());
        assert!(take("[program]\nloads = [1.0, # c\n 2.0]\n").is_none());
        assert!(take("x = '''\n[program]\nloads = [1.0]\n'''\n").is_none());
    }
}
