//! Length units as instruments spell them, to metres.

/// Metres per unit of a length unit as written in a file, or `None` when
/// `unit` is no length unit. Accepts SI prefixes from pm to km with `m`,
/// the micro sign (`µm`, `μm`), `um`, the Nanoscope and Digital Surf
/// spellings of micrometres (`~m`, Latin-1 `æm`), and the ångström (`Å`,
/// `A`, `Ang`, `angstrom`; `A` only where `ampere_a` is false: Igor files
/// use SI symbols, so there `A` is the ampere).
pub fn metres_per(unit: &str, ampere_a: bool) -> Option<f64> {
    let u = unit.trim();
    Some(match u {
        "m" | "meter" | "meters" | "metre" | "metres" => 1.0,
        "km" => 1e3,
        "cm" => 1e-2,
        "mm" => 1e-3,
        "um" | "µm" | "μm" | "~m" | "æm" | "micron" | "microns" | "micrometer" | "micrometre" => {
            1e-6
        }
        "nm" | "nanometer" | "nanometre" => 1e-9,
        "Å" | "Ang" | "angstrom" | "Angstrom" => 1e-10,
        "A" if !ampere_a => 1e-10,
        "pm" => 1e-12,
        _ => return None,
    })
}

/// The canonical spelling of a length unit (`um` for every spelling of
/// micrometres), or the unit as given when it is no length unit.
pub fn canonical(unit: &str, ampere_a: bool) -> String {
    let names = [
        (1.0, "m"),
        (1e3, "km"),
        (1e-2, "cm"),
        (1e-3, "mm"),
        (1e-6, "um"),
        (1e-9, "nm"),
        (1e-10, "A"),
        (1e-12, "pm"),
    ];
    metres_per(unit, ampere_a)
        .and_then(|f| names.iter().find(|(m, _)| *m == f))
        .map_or_else(|| unit.trim().to_string(), |(_, n)| (*n).to_string())
}

/// The height unit of a `.npy` or text map, which carries none
/// (`--height-unit`, scene key `surface.height_unit`): `nm`, `um` or `m`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum HeightUnit {
    /// Nanometres (1e-9 m).
    Nm,
    /// Micrometres (1e-6 m).
    Um,
    /// Metres.
    M,
}

impl HeightUnit {
    /// Metres per unit.
    pub fn metres(self) -> f64 {
        match self {
            HeightUnit::Nm => 1e-9,
            HeightUnit::Um => 1e-6,
            HeightUnit::M => 1.0,
        }
    }
}

impl crate::named::Named for HeightUnit {
    const ALL: &'static [Self] = &[HeightUnit::Nm, HeightUnit::Um, HeightUnit::M];
    const WHAT: &'static str = "height unit";
    fn name(self) -> &'static str {
        match self {
            HeightUnit::Nm => "nm",
            HeightUnit::Um => "um",
            HeightUnit::M => "m",
        }
    }
}
crate::serde_by_name!(HeightUnit);

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn spellings_of_the_same_unit_agree() {
        for u in ["um", "µm", "μm", "~m", "æm", " um "] {
            assert_eq!(metres_per(u, false), Some(1e-6), "{u}");
            assert_eq!(canonical(u, false), "um");
        }
        assert_eq!(metres_per("A", false), Some(1e-10));
        assert_eq!(metres_per("A", true), None);
        assert_eq!(metres_per("V", false), None);
        assert_eq!(canonical("V", false), "V");
    }

    #[test]
    fn height_units_by_name() {
        use crate::named::Named;
        assert_eq!(HeightUnit::parse("nm").unwrap().metres(), 1e-9);
        assert_eq!(HeightUnit::parse("um").unwrap().metres(), 1e-6);
        assert_eq!(HeightUnit::parse("m").unwrap().metres(), 1.0);
        let e = HeightUnit::parse("mm").unwrap_err().to_string();
        assert!(e.contains("nm, um, m"), "{e}");
    }
}
