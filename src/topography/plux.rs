//! Sensofar `.plux` (the S neox and S lynx confocal and interferometric
//! profilers): a zip archive holding `index.xml`, `recipe.txt` and one
//! binary member per layer.
//!
//! Layout (reverse-documented by SurfaceTopography's `PLUX.py`, which this
//! reader follows): `index.xml` has the root `xml` with `GENERAL`
//! (`IMAGE_SIZE_X`, `IMAGE_SIZE_Y`: the points along x and y; `FOV_X`,
//! `FOV_Y`: the pixel sizes in um) and one `LAYER_k` per layer (`k` from 0,
//! consecutive) whose `FILENAME_Z` names the member with the heights:
//! `IMAGE_SIZE_Y` rows of `IMAGE_SIZE_X` little-endian float32 values in
//! um, x fastest (exactly that many bytes). NaN heights are missing. The
//! channels are named `Layer k`; the default is layer 0.

use super::x3p::heights;
use super::{pick, pixel, Bad, Channel, Format, Measured};

pub(super) fn read(bytes: &[u8], channel: &Channel) -> Result<Measured, Bad> {
    let mut zip = super::x3p::open_zip(bytes)?;
    let x = super::x3p::Leaves::read(&mut zip, "index.xml")?;
    let (nx, ny) = (
        x.count("GENERAL/IMAGE_SIZE_X")?,
        x.count("GENERAL/IMAGE_SIZE_Y")?,
    );
    super::dims(ny, nx)?;
    let (dx, dy) = (
        x.num("GENERAL/FOV_X")? * 1e-6,
        x.num("GENERAL/FOV_Y")? * 1e-6,
    );
    let layers: Vec<String> = (0..)
        .map_while(|k| {
            x.optional(&format!("LAYER_{k}/FILENAME_Z"))
                .map(str::to_string)
        })
        .collect();
    if layers.is_empty() {
        return Err(Bad::corrupt("index.xml has no LAYER_0/FILENAME_Z"));
    }
    let names: Vec<String> = (0..layers.len()).map(|k| format!("Layer {k}")).collect();
    let k = pick(&names, 0, channel)?;
    let link = &layers[k];
    let want = nx as u64 * ny as u64 * 4;
    let size = zip
        .by_name(link)
        .map_err(|e| Bad::corrupt(format!("no member '{link}' in the archive ({e})")))?
        .size();
    if size != want {
        return Err(Bad::corrupt(format!(
            "member '{link}' holds {size} bytes; {ny} x {nx} float32 values need {want}"
        )));
    }
    let z = heights(bytes, &mut zip, link, ny, nx, |b| {
        let v = f64::from(f32::from_le_bytes(b)) * 1e-6;
        if v.is_finite() {
            v
        } else {
            f64::NAN
        }
    })?;
    Ok(Measured {
        format: Format::Plux,
        channel: names[k].clone(),
        channels: names,
        unit: "um".into(),
        rows: ny,
        cols: nx,
        heights: z,
        pixel_size: Some((pixel(dx, "x")?, pixel(dy, "y")?)),
        periodic: false,
    })
}
