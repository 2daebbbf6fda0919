//! Gold, the metal of the default microswitch study: every number the
//! gold defaults use lives here ([`super::Material::gold`],
//! [`super::AsperityContact::gold_microswitch`],
//! [`crate::gw::RoughSurface::gold_microswitch`],
//! [`super::plastic::Plasticity::gold`],
//! [`crate::electrical::Conductor::GOLD`], the heating limits, the
//! embedded default scene).

/// Young's modulus `E` (Pa): polycrystalline gold, 79 GPa.
pub const YOUNGS_MODULUS: f64 = 79e9;

/// Poisson ratio `nu`: 0.42.
pub const POISSON_RATIO: f64 = 0.42;

/// Work of adhesion `w` of gold on gold (J/m^2): 0.5 (clean metal
/// contacts in MEMS switches; twice a surface energy of ~0.25 J/m^2 after
/// contamination).
pub const WORK_OF_ADHESION: f64 = 0.5;

/// Equilibrium separation `z0` of the Lennard-Jones law (m): 0.3 nm.
pub const FORCE_RANGE: f64 = 0.3e-9;

/// Yield strength `Y` of sputtered RF-MEMS gold (Pa): 0.4 GPa.
pub const YIELD_STRENGTH: f64 = 0.4e9;

/// Resistivity at 293 K (Ohm m): 2.44e-8 (CRC Handbook).
pub const RESISTIVITY: f64 = 2.44e-8;

/// Electron mean free path at room temperature (m): 34.6 nm (Gall 2016,
/// J. Appl. Phys. 119, 085101).
pub const MEAN_FREE_PATH: f64 = 3.46e-8;

/// Softening temperature (K), 100 °C (Holm 1967, table of softening and
/// melting voltages).
pub const SOFTENING_TEMPERATURE: f64 = 373.15;

/// Melting temperature (K), 1337.33 K (ITS-90 fixed point).
pub const MELTING_TEMPERATURE: f64 = 1337.33;

/// Summit radius `R` of the default switch surface (m): 1 um.
pub const SUMMIT_RADIUS: f64 = 1e-6;

/// Summit density `eta` of the default switch surface (1/m^2): 1e12.
pub const SUMMIT_DENSITY: f64 = 1e12;

/// Summit-height standard deviation `sigma` of the default switch surface
/// (m): 5 nm.
pub const SUMMIT_SIGMA: f64 = 5e-9;

/// Nominal area of the default switch contact (m^2): 100 um x 100 um.
pub const NOMINAL_AREA: f64 = 1e-8;
