//! Scenes: one TOML file describes a contact study (materials, surface,
//! adhesion, law, loading program, outputs, accuracy).
//!
//! [`Scene::from_toml`] parses and validates; field errors name the dotted
//! path (`surface.sigma`) and, for parse errors, the line;
//! [`build_contact`], [`build_surface`] and [`build_distribution`] turn
//! its values into core objects, mapping the core's errors onto scene
//! fields. The planner ([`crate::study::plan`]) decides what to compute.
//! [`scene_schema`] is the scene files' JSON Schema, derived from the same
//! types; [`keys_at`] and [`nearest_key`] read the allowed keys from it.

mod build;
mod features;
mod json_schema;
mod keys;
mod law_name;
mod limits;
mod listed;
mod parse;
mod schema;
mod summit_source;
mod topography;

pub use build::{
    build_contact, build_distribution, build_surface, decades_from_typical, map_derived,
    most_extreme_input, SPHERE_REFERENCE_AREA,
};
pub use features::ProgramTarget;
pub use json_schema::{scene_schema, scene_schema_text, SCHEMA_DIALECT, UNIT_KEYWORD};
pub use keys::{keys_at, nearest_key, scene_keys, suggest_key, SchemaKey};
pub use law_name::LawName;
pub use topography::{read_map, resolve, Resolved, SummitSource, TopographySpec};

pub use limits::{DEFAULT_POPULATIONS, DEFAULT_SEED, MAX_LISTED_STATES, MAX_POPULATIONS};
pub use schema::{
    AccuracySpec, AdhesionSpec, ElectricalSpec, LawSpec, MaterialsSpec, MonteCarloSpec,
    OutputsSpec, ProgramSpec, Scene, SphereShape, SphereSpec, SurfaceSpec, SwitchSpec,
};

/// The reference scene of the tests and examples
/// (`examples/scenes/mems-gold.toml`: the gold microswitch surface with the
/// law chosen by `auto`), embedded so that it runs anywhere.
pub const DEFAULT_SCENE: &str = include_str!("../../../examples/scenes/mems-gold.toml");

/// The default study that `asperity` with no arguments (and `cargo run
/// --release`) runs: the ohmic RF-MEMS switch of
/// `examples/scenes/rf-mems-switch.toml` (gold with a yield strength,
/// Kogut–Etsion summits with adhesion after yield, contact resistance
/// against force, the pull-off distribution of one switch and its stiction
/// probability for the stated spring and travel).
pub const DEFAULT_STUDY: &str = include_str!("../../../examples/scenes/rf-mems-switch.toml");

#[cfg(test)]
mod tests {
    use super::*;

    fn with(old: &str, new: &str) -> String {
        assert!(DEFAULT_SCENE.contains(old), "{old}");
        DEFAULT_SCENE.replacen(old, new, 1)
    }

    fn field_of(text: &str) -> (String, String) {
        let e = Scene::from_toml(text).unwrap_err();
        (e.field().unwrap_or("").to_string(), e.to_string())
    }

    #[test]
    fn default_scene_parses_and_round_trips() {
        let s = Scene::from_toml(DEFAULT_SCENE).unwrap();
        assert_eq!(s.surface.sigma, 5e-9);
        assert_eq!(s.law.kind, LawName::Auto);
        let back = Scene::from_toml(&s.to_toml()).unwrap();
        assert_eq!(back, s);
    }

    #[test]
    fn bad_scenes_name_their_field() {
        let cases = [
            (with("sigma = 5e-9", "sigma = -5e-9"), "surface.sigma"),
            (with("sigma = 5e-9", "sigma = nan"), "surface.sigma"),
            (with("sigma = 5e-9", "sigmaa = 5e-9"), "surface.sigmaa"),
            (with("sigma = 5e-9            #", "#"), "surface.sigma"),
            (with("kind = \"auto\"", "kind = \"hertzz\""), "law.kind"),
            (with("nu1 = 0.42", "nu1 = 0.5"), "materials.nu1"),
            (with("e2 = 79e9", "e2 = \"stiff\""), "materials.e2"),
            (with("rtol = 1e-6", "rtol = 0.5"), "accuracy.rtol"),
            (with("points = 200", "points = 1"), "program.points"),
            (with("w = 0.5", "w = -0.5"), "adhesion.w"),
            (
                with("distribution = \"gaussian\"", "distribution = \"lorentz\""),
                "surface.distribution",
            ),
        ];
        for (text, field) in cases {
            let (got, msg) = field_of(&text);
            assert_eq!(got, field, "{msg}");
        }
    }

    #[test]
    fn montecarlo_section_is_validated() {
        for (extra, field) in [
            ("summits = 0", "montecarlo.summits"),
            ("summits = 2000000000", "montecarlo.summits"),
            ("radius_log_std = -0.1", "montecarlo.radius_log_std"),
            ("radius_log_std = nan", "montecarlo.radius_log_std"),
            ("seeds = 0", "montecarlo.seeds"),
            ("seeds = 1000000000", "montecarlo.seeds"),
            ("seed = -1", "montecarlo.seed"),
        ] {
            let text = format!("{DEFAULT_SCENE}\n[montecarlo]\n{extra}\n");
            let (got, msg) = field_of(&text);
            assert_eq!(got, field, "{extra}: {msg}");
        }
        let ok = format!("{DEFAULT_SCENE}\n[montecarlo]\nseed = 3\n");
        let s = Scene::from_toml(&ok).unwrap();
        assert_eq!(s.montecarlo.unwrap().seed, 3);
        assert_eq!(Scene::from_toml(&s.to_toml()).unwrap(), s);
    }

    #[test]
    fn parse_errors_carry_the_line() {
        let text = with("sigma = 5e-9", "sigmaa = 5e-9");
        let line = text.lines().position(|l| l.starts_with("sigmaa")).unwrap() + 1;
        let (_, msg) = field_of(&text);
        assert!(msg.contains(&format!("line {line}")), "{msg}");
    }

    #[test]
    fn a_missing_table_is_named_alone() {
        // The scene opens with comments; a missing top-level table is
        // named as itself, not after the first line's text.
        let start = DEFAULT_SCENE.find("[adhesion]").unwrap();
        let end = start + DEFAULT_SCENE[start..].find("\n[").unwrap() + 1;
        let text = format!("{}{}", &DEFAULT_SCENE[..start], &DEFAULT_SCENE[end..]);
        assert!(text.starts_with('#'));
        assert_eq!(field_of(&text).0, "adhesion");
        let bare = text
            .lines()
            .filter(|l| !l.starts_with('#'))
            .collect::<Vec<_>>()
            .join("\n");
        assert!(bare.starts_with("title") || bare.starts_with('['), "{bare}");
        assert_eq!(field_of(&bare).0, "adhesion");
        // A missing key inside a table keeps the table's path.
        let (field, msg) = field_of(&with("e1 = ", "# e1 = "));
        assert_eq!(field, "materials.e1", "{msg}");
    }

    #[test]
    fn program_needs_exactly_one_target() {
        let both = with("points = 200", "points = 200\nmax_load = 1e-4");
        assert_eq!(field_of(&both).0, "program");
        let none = with("closest_separation = 5e-9", "");
        assert_eq!(field_of(&none).0, "program");
    }
}
