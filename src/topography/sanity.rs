//! What a map's file and its user say about its scale: the pixel sizes
//! from the file or the user (and which to trust when they disagree), and
//! the warnings that a height or length unit is probably wrong.

use super::Format;
use crate::error::{Error, Result};

/// How far a pixel size given beside a file's may differ from it,
/// relative.
pub const PIXEL_AGREEMENT: f64 = 1e-9;

/// The pixel sizes `(dx, dy)` (m) of a map of `format` whose file gives
/// `file` (if any), with `given` (named `name`, square) from the user, and
/// the warnings on the way: the file's when `given` is absent or agrees
/// with both of them to [`PIXEL_AGREEMENT`] relative; `given` when the
/// file has none, or, with a warning naming both values, when they
/// disagree.
///
/// # Errors
/// [`Error::Invalid`] naming `name` when neither gives one;
/// [`Error::OutOfRange`] naming it when `given` is not positive.
pub fn pixel_sizes(
    file: Option<(f64, f64)>,
    given: Option<f64>,
    name: &str,
    format: Format,
) -> Result<((f64, f64), Vec<String>)> {
    if let Some(p) = given {
        crate::error::positive(name, p)?;
    }
    match (file, given) {
        (None, None) => Err(Error::invalid(
            name,
            format!("required: a {} file gives no pixel size", format.describe()),
        )),
        (None, Some(p)) => Ok(((p, p), Vec::new())),
        (Some(d), None) => Ok((d, Vec::new())),
        (Some((dx, dy)), Some(p)) => {
            let agree = |a: f64| (p - a).abs() <= PIXEL_AGREEMENT * a;
            if agree(dx) && agree(dy) {
                Ok(((dx, dy), Vec::new()))
            } else {
                Ok((
                    (p, p),
                    vec![format!(
                        "{name} = {p:e} m disagrees with the file's pixels of {dx:e} m (x) by \
                         {dy:e} m (y) beyond {PIXEL_AGREEMENT:e} relative: using {name}; omit it \
                         to trust the file"
                    )],
                ))
            }
        }
    }
}

/// Warnings that a unit is probably wrong: an RMS height above 10 um, a
/// pixel above 1 mm or below 0.1 nm, each naming the value and the unit it
/// probably was in; `height_unit` and `scale` name the inputs that fix a
/// height unit.
pub fn unit_warnings(
    rms_height: f64,
    (dx, dy): (f64, f64),
    height_unit: &str,
    scale: &str,
) -> Vec<String> {
    // The units that would make a value plausible (an RMS height of 0.1 nm
    // to 10 um, a pixel of 0.1 nm to 1 mm), with the value they give.
    let likely = |v: f64, hi: f64| -> String {
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
    };
    let mut out = Vec::new();
    if rms_height > 1e-5 {
        out.push(format!(
            "the RMS height {rms_height:.3e} m is above 10 um: the height unit is probably wrong, \
             heights in {} read as m? (give {height_unit}, or {scale})",
            likely(rms_height, 1e-5)
        ));
    }
    for (axis, d) in [("x", dx), ("y", dy)] {
        if d > 1e-3 {
            out.push(format!(
                "the pixel size along {axis}, {d:.3e} m, is above 1 mm: the length unit is \
                 probably wrong, a size in {} read as m?",
                likely(d, 1e-3)
            ));
        } else if d < 1e-10 {
            out.push(format!(
                "the pixel size along {axis}, {d:.3e} m, is below 0.1 nm: the length unit is \
                 probably wrong, a size in m ({:.3e} m if it was in um, {:.3e} m if in nm) \
                 converted once more?",
                d * 1e6,
                d * 1e9
            ));
        }
        if dx == dy {
            break;
        }
    }
    out
}
