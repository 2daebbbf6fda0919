//! The map-reading flags `asperity surface` and `asperity bem` share
//! (`--channel`, `--fill-missing`, `--height-unit`, `--scale`,
//! `--pixel-size`, `--export`), turned into one read.

use asperity::commands::measured::{export, height_unit, read_measured, MeasuredMap, ReadOptions};
use asperity::commands::CommandResult;
use asperity::topography::Channel;
use clap::Args;
use std::path::{Path, PathBuf};

/// The map-reading flags of `asperity surface` and `asperity bem`, one
/// definition flattened into both (`bem` words `--scale` and `--export`
/// its own way with `mut_arg`).
#[derive(Args, Debug)]
pub struct MapArgs {
    /// Pixel size (m), the same along x and y; needed for `.npy` and text
    /// maps. Given for a file that has its own, it must agree to 1e-9 or it
    /// wins with a warning.
    #[arg(long, allow_hyphen_values = true)]
    pub pixel_size: Option<f64>,
    /// Unit of a `.npy` or text map's heights: nm, um or m (default m).
    #[arg(long)]
    pub height_unit: Option<String>,
    /// Factor on the heights after their unit (e.g. 1e-9 for nm).
    #[arg(long, allow_hyphen_values = true, default_value_t = 1.0)]
    pub scale: f64,
    /// The channel of a file with several, by name or index from 0 (default:
    /// the height channel).
    #[arg(long)]
    pub channel: Option<String>,
    /// Fill missing pixels (NaN or masked in the file) from their neighbours
    /// instead of refusing the map.
    #[arg(long)]
    pub fill_missing: bool,
    /// Also write the map read, in m, to this `.x3p` (with its pixel sizes)
    /// or `.npy` file.
    #[arg(long)]
    pub export: Option<PathBuf>,
}

/// Reads `path` as the flags say and writes `--export` when given: the
/// map, its pixel sizes `(dx, dy)` (m) and the warnings about them.
pub fn read_map(path: &Path, f: &MapArgs) -> CommandResult<(MeasuredMap, (f64, f64), Vec<String>)> {
    let options = ReadOptions {
        channel: f
            .channel
            .as_deref()
            .map_or(Channel::Default, Channel::parse),
        fill_missing: f.fill_missing,
        height_unit: f.height_unit.as_deref().map(height_unit).transpose()?,
        scale: f.scale,
    };
    let read = read_measured(path, &options)?;
    let (pixels, mismatch) = read.pixels(f.pixel_size)?;
    if let Some(out) = &f.export {
        export(out, &read.map, pixels)?;
    }
    Ok((
        read,
        pixels,
        mismatch.iter().map(ToString::to_string).collect(),
    ))
}
