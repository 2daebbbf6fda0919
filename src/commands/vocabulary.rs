//! How each front end names a command's inputs in messages.
//!
//! Commands write an input's parameter name in braces inside their errors
//! (`{pixel_size} = -1 is out of range`, `give only one of {pressures} and
//! {gaps}`); [`Vocabulary::render`] replaces each by the front end's word:
//! `--pixel-size` on the command line, `pixel_size` in Python. An entry of a
//! list, `{pressures[2]}`, is the flag on the command line (a list is one
//! flag there) and `pressures[2]` in Python.

use crate::Error;

/// The parameter `name` as commands write it in messages: `{name}`.
pub fn param(name: &str) -> String {
    format!("{{{name}}}")
}

/// How a front end spells inputs.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Style {
    /// `--dashed-flag`.
    Flags,
    /// `keyword_argument` (a Python keyword gets a trailing underscore:
    /// `lambda_`).
    Keywords,
}

/// A front end's words for a command's inputs: a style plus the names it
/// spells otherwise (the command line's `--radius` for `punch_radius`, the
/// map's file for `heights`).
#[derive(Debug, Clone)]
pub struct Vocabulary {
    style: Style,
    words: Vec<(String, String)>,
}

/// Python's keywords that cannot be argument names.
const PYTHON_KEYWORDS: [&str; 4] = ["lambda", "from", "in", "is"];

impl Vocabulary {
    /// The command line: inputs are flags (`pixel_size` -> `--pixel-size`).
    pub fn cli() -> Self {
        Vocabulary {
            style: Style::Flags,
            words: Vec::new(),
        }
    }

    /// Python: inputs are keyword arguments (`pixel_size`; `lambda` ->
    /// `lambda_`).
    pub fn python() -> Self {
        Vocabulary {
            style: Style::Keywords,
            words: Vec::new(),
        }
    }

    /// The same vocabulary spelling `name` as `word` (e.g. the command
    /// line's `punch_radius` is `--radius`; its `heights` are a file).
    #[must_use]
    pub fn with(mut self, name: &str, word: impl Into<String>) -> Self {
        self.words.push((name.to_string(), word.into()));
        self
    }

    /// The word for parameter `name` (entry `index` of a list, if any).
    pub fn word(&self, name: &str, index: Option<&str>) -> String {
        if let Some((_, w)) = self.words.iter().find(|(n, _)| n == name) {
            return match (self.style, index) {
                (Style::Keywords, Some(i)) => format!("{w}[{i}]"),
                _ => w.clone(),
            };
        }
        match self.style {
            Style::Flags => format!("--{}", name.replace('_', "-")),
            Style::Keywords => {
                let base = if PYTHON_KEYWORDS.contains(&name) {
                    format!("{name}_")
                } else {
                    name.to_string()
                };
                match index {
                    Some(i) => format!("{base}[{i}]"),
                    None => base,
                }
            }
        }
    }

    /// `text` with every `{name}` and `{name[i]}` replaced by its word; any
    /// other brace is kept.
    pub fn words_in(&self, text: &str) -> String {
        let mut out = String::with_capacity(text.len());
        let mut rest = text;
        while let Some(open) = rest.find('{') {
            out.push_str(&rest[..open]);
            let after = &rest[open + 1..];
            match after.find('}').and_then(|close| {
                let inner = &after[..close];
                parse_param(inner).map(|(n, i)| (close, self.word(n, i)))
            }) {
                Some((close, word)) => {
                    out.push_str(&word);
                    rest = &after[close + 1..];
                }
                None => {
                    out.push('{');
                    rest = after;
                }
            }
        }
        out.push_str(rest);
        out
    }

    /// The message of `e` in this vocabulary.
    pub fn render(&self, e: &Error) -> String {
        self.words_in(&e.to_string())
    }
}

/// `name` or `name[index]` of a parameter written in braces: lower-case
/// letters, digits and underscores, starting with a letter.
fn parse_param(inner: &str) -> Option<(&str, Option<&str>)> {
    let (name, index) = match inner.split_once('[') {
        Some((n, rest)) => (n, Some(rest.strip_suffix(']')?)),
        None => (inner, None),
    };
    let ident = name.chars().next().is_some_and(|c| c.is_ascii_lowercase())
        && name
            .chars()
            .all(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || c == '_');
    let index_ok = index.is_none_or(|i| !i.is_empty() && i.chars().all(|c| c.is_ascii_digit()));
    (ident && index_ok).then_some((name, index))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_front_end_words_the_inputs() {
        // `e` as the command line and as Python word it.
        let renders = |e: &Error, cli: &str, python: &str| {
            assert_eq!(Vocabulary::cli().render(e), cli);
            assert_eq!(Vocabulary::python().render(e), python);
        };
        let e = crate::error::positive(&param("pixel_size"), -1.0).unwrap_err();
        renders(
            &e,
            "--pixel-size = -1 is out of range: allowed finite, in (0, inf)",
            "pixel_size = -1 is out of range: allowed finite, in (0, inf)",
        );
        let e = Error::invalid(
            format!("{}, {}", param("pressures"), param("gaps")),
            "give only one of them",
        );
        renders(
            &e,
            "--pressures, --gaps: give only one of them",
            "pressures, gaps: give only one of them",
        );
        let e = Error::invalid(param("pressures[3]"), "not a number");
        renders(
            &e,
            "--pressures: not a number",
            "pressures[3]: not a number",
        );
        assert_eq!(Vocabulary::python().word("lambda", None), "lambda_");
        let v = Vocabulary::cli().with("punch_radius", "--radius");
        assert_eq!(v.words_in("{punch_radius} = 2"), "--radius = 2");
    }

    #[test]
    fn other_braces_are_kept() {
        for text in ["{}", "{ a = 1 }", "{Upper}", "{x[}", "{x[a]}", "a {b", "}{"] {
            assert_eq!(Vocabulary::cli().words_in(text), text);
        }
        assert_eq!(Vocabulary::cli().words_in("{{d}}"), "{--d}");
    }
}
