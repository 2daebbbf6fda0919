//! The map-reading flags `asperity surface` and `asperity bem` share
//! (`--channel`, `--fill-missing`, `--height-unit`, `--scale`,
//! `--pixel-size`, `--export`), turned into one read.

use asperity::commands::measured::{export, height_unit, read_measured, MeasuredMap, ReadOptions};
use asperity::commands::CommandResult;
use asperity::topography::Channel;
use std::path::Path;

/// The flags of one map read.
pub struct MapFlags<'a> {
    pub channel: Option<&'a str>,
    pub fill_missing: bool,
    pub height_unit: Option<&'a str>,
    pub scale: f64,
    pub pixel_size: Option<f64>,
    pub export: Option<&'a Path>,
}

/// Reads `path` as the flags say and writes `--export` when given: the
/// map, its pixel sizes `(dx, dy)` (m) and the warnings about them.
pub fn read_map(
    path: &Path,
    f: &MapFlags,
) -> CommandResult<(MeasuredMap, (f64, f64), Vec<String>)> {
    let options = ReadOptions {
        channel: f.channel.map_or(Channel::Default, Channel::parse),
        fill_missing: f.fill_missing,
        height_unit: f.height_unit.map(height_unit).transpose()?,
        scale: f.scale,
    };
    let read = read_measured(path, &options)?;
    let (pixels, warnings) = read.pixels(f.pixel_size)?;
    if let Some(out) = f.export {
        export(out, &read.map, pixels)?;
    }
    Ok((read, pixels, warnings))
}
