//! What a map's file and its user say about its scale: the pixel sizes
//! from the file or the user (and which to trust when they disagree), and
//! the warnings that a height or length unit is probably wrong.

use super::Format;
use crate::error::{Error, Result};
use std::fmt;

/// How far a pixel size given beside a file's may differ from it,
/// relative.
pub const PIXEL_AGREEMENT: f64 = 1e-9;

/// A pixel size given beside a file's that disagrees with it beyond
/// [`PIXEL_AGREEMENT`] relative: the given one is used. `Display` words the
/// warning.
#[derive(Debug, Clone, PartialEq)]
pub struct PixelSizeMismatch {
    /// How the given pixel size is named (`surface.pixel_size`,
    /// `{pixel_size}`).
    pub name: String,
    /// The pixel size given (m), square.
    pub given: f64,
    /// The file's pixel sizes `(dx, dy)` (m).
    pub file: (f64, f64),
}

impl fmt::Display for PixelSizeMismatch {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let (name, p, (dx, dy)) = (&self.name, self.given, self.file);
        write!(
            f,
            "{name} = {p:e} m disagrees with the file's pixels of {dx:e} m (x) by {dy:e} m (y) \
             beyond {PIXEL_AGREEMENT:e} relative: using {name}; omit it to trust the file"
        )
    }
}

/// The pixel sizes `(dx, dy)` (m) of a map of `format` whose file gives
/// `file` (if any), with `given` (named `name`, square) from the user, and
/// the warning on the way: the file's when `given` is absent or agrees
/// with both of them to [`PIXEL_AGREEMENT`] relative; `given` when the
/// file has none, or, with a [`PixelSizeMismatch`], when they disagree.
///
/// # Errors
/// [`Error::Invalid`] naming `name` when neither gives one;
/// [`Error::OutOfRange`] naming it when `given` is not positive.
pub fn pixel_sizes(
    file: Option<(f64, f64)>,
    given: Option<f64>,
    name: &str,
    format: Format,
) -> Result<((f64, f64), Option<PixelSizeMismatch>)> {
    if let Some(p) = given {
        crate::error::positive(name, p)?;
    }
    match (file, given) {
        (None, None) => Err(Error::invalid(
            name,
            format!("required: a {} file gives no pixel size", format.describe()),
        )),
        (None, Some(p)) => Ok(((p, p), None)),
        (Some(d), None) => Ok((d, None)),
        (Some((dx, dy)), Some(p)) => {
            let agree = |a: f64| (p - a).abs() <= PIXEL_AGREEMENT * a;
            if agree(dx) && agree(dy) {
                Ok(((dx, dy), None))
            } else {
                let mismatch = PixelSizeMismatch {
                    name: name.to_string(),
                    given: p,
                    file: (dx, dy),
                };
                Ok(((p, p), Some(mismatch)))
            }
        }
    }
}

/// A unit that is probably wrong: an RMS height above 10 um, a pixel above
/// 1 mm or below 0.1 nm. `Display` words the warning, naming the value and
/// the units it would be plausible in (an RMS height of 0.1 nm to 10 um, a
/// pixel of 0.1 nm to 1 mm).
#[derive(Debug, Clone, PartialEq)]
pub enum UnitWarning {
    /// The RMS height (m) is above 10 um.
    RmsHeight {
        /// The RMS height (m).
        rms_height: f64,
        /// The inputs that set a height unit (`surface.height_unit =
        /// "m" | ...`, `{height_unit}`).
        height_unit: String,
        /// The input that scales the heights (`surface.height_scale`,
        /// `{scale}`).
        scale: String,
    },
    /// The pixel size (m) along `axis` is above 1 mm.
    PixelAbove {
        /// `x` or `y`.
        axis: char,
        /// The pixel size (m).
        size: f64,
    },
    /// The pixel size (m) along `axis` is below 0.1 nm.
    PixelBelow {
        /// `x` or `y`.
        axis: char,
        /// The pixel size (m).
        size: f64,
    },
}

impl fmt::Display for UnitWarning {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            UnitWarning::RmsHeight {
                rms_height,
                height_unit,
                scale,
            } => write!(
                f,
                "the RMS height {rms_height:.3e} m is above 10 um: the height unit is probably \
                 wrong, heights in {} read as m? (give {height_unit}, or {scale})",
                likely(*rms_height, 1e-5)
            ),
            UnitWarning::PixelAbove { axis, size: d } => write!(
                f,
                "the pixel size along {axis}, {d:.3e} m, is above 1 mm: the length unit is \
                 probably wrong, a size in {} read as m?",
                likely(*d, 1e-3)
            ),
            UnitWarning::PixelBelow { axis, size: d } => write!(
                f,
                "the pixel size along {axis}, {d:.3e} m, is below 0.1 nm: the length unit is \
                 probably wrong, a size in m ({:.3e} m if it was in um, {:.3e} m if in nm) \
                 converted once more?",
                d * 1e6,
                d * 1e9
            ),
        }
    }
}

/// The units that would make a value `v` read as m plausible (from 0.1 nm
/// to `hi` m), with the value they give.
fn likely(v: f64, hi: f64) -> String {
    let fits: Vec<String> = [("mm", 1e-3), ("um", 1e-6), ("nm", 1e-9)]
        .iter()
        .filter(|(_, f)| (1e-10..=hi).contains(&(v * f)))
        .map(|(u, f)| format!("{u} ({:.3e} m)", v * f))
        .collect();
    if fits.is_empty() {
        "a smaller unit".into()
    } else {
        fits.join(" or ")
    }
}

/// Warnings that a unit is probably wrong ([`UnitWarning`]): an RMS height
/// above 10 um, a pixel above 1 mm or below 0.1 nm (each axis, once when
/// square); `height_unit` and `scale` name the inputs that fix a height
/// unit.
pub fn unit_warnings(
    rms_height: f64,
    (dx, dy): (f64, f64),
    height_unit: &str,
    scale: &str,
) -> Vec<UnitWarning> {
    let mut out = Vec::new();
    if rms_height > 1e-5 {
        out.push(UnitWarning::RmsHeight {
            rms_height,
            height_unit: height_unit.to_string(),
            scale: scale.to_string(),
        });
    }
    for (axis, d) in [('x', dx), ('y', dy)] {
        if d > 1e-3 {
            out.push(UnitWarning::PixelAbove { axis, size: d });
        } else if d < 1e-10 {
            out.push(UnitWarning::PixelBelow { axis, size: d });
        }
        if dx == dy {
            break;
        }
    }
    out
}
