//! Measured maps as instruments write them: AFM, profilometer and
//! interferometer files, with their pixel sizes, channels and units.
//!
//! Each reader follows a published or reverse-documented layout (the
//! source of truth of each is in `docs/surface.md`, "Measured maps") and
//! parses from memory: [`read_bytes`] takes the file's bytes, [`read`] a
//! path. Every reader gives the heights in metres (row `i` along y, column
//! `j` along x, row-major, as [`crate::surface::HeightMap`]), the pixel
//! sizes along x and y in metres when the file has them, the channel's name,
//! the instrument's height unit and whether the file says the map is
//! periodic (never otherwise). Missing pixels (NaN, masked, out of range)
//! are NaN here and counted: [`Measured::into_map`] refuses them, or
//! [`Measured::fill_missing`] fills them when asked.
//!
//! Bad files (truncated, wrong magic, inconsistent headers, a dimension
//! larger than the file can hold) give [`crate::Error::Invalid`] naming the
//! file, the format and the reason; no reader panics or allocates more than
//! its file can describe (`tests/topography_fuzz.rs` truncates and garbles
//! every sample).
//!
//! This module belongs to the `study` feature: the physics core parses no
//! instrument files and gains no dependency from them.

mod bytes;
mod di;
mod fill;
mod frt;
mod gwy;
mod ibw;
mod inflate;
mod mapped;
mod md5;
mod nc;
mod opd;
mod opdx;
mod plux;
mod sanity;
mod sdf;
mod sur;
pub mod units;
mod x3p;

pub use sanity::{pixel_sizes, unit_warnings, PixelSizeMismatch, UnitWarning, PIXEL_AGREEMENT};
pub use x3p::to_x3p;

use crate::error::{Error, Result};
use crate::surface::HeightMap;
use serde::Serialize;
use std::path::Path;

/// Most pixels a map may declare (2^31, 17 GB of heights): a header
/// beyond is refused before anything is allocated.
pub const MAX_PIXELS: usize = 1 << 31;

/// Peak memory (bytes) per pixel a map's header declares, of reading and
/// characterising it: the heights (8), one map-sized working copy a reader
/// or a command may make (8: an inflated X3P member, a transposed or
/// flipped map, a filled or scaled copy) and the summits at their most (8:
/// one per 2 x 2 pixels, 32 bytes each). The file itself is memory-mapped:
/// its pages are the page cache's, not counted. A header declaring more
/// than the memory available is refused before anything is allocated.
pub const BYTES_PER_PIXEL: f64 = 24.0;

/// The same for a float64 `.npy` read where it lies ([`read_npy`]): no
/// heights of its own, only the working copy and the summits.
pub const NPY_MAPPED_BYTES_PER_PIXEL: f64 = 16.0;

/// A file format asperity reads.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Format {
    /// NumPy `.npy` (heights in the unit of `--height-unit`, m by default).
    Npy,
    /// A text matrix `.txt`, `.csv`, `.asc`.
    Text,
    /// ISO 25178-72 XML 3D surface profile `.x3p`.
    X3p,
    /// ISO 25178-71 surface data file `.sdf`, ASCII or binary.
    Sdf,
    /// Gwyddion native `.gwy`.
    Gwy,
    /// Digital Surf `.sur`.
    Sur,
    /// Bruker/Veeco/Digital Instruments Nanoscope `.di`, `.spm`, `.001`...
    Nanoscope,
    /// Igor binary wave `.ibw` (Asylum Research AFMs).
    Ibw,
    /// Wyko/Bruker Vision `.opd`.
    Opd,
    /// Bruker Dektak Vision64 `.opdx`.
    Opdx,
    /// NetCDF-3 `.nc` (SurfaceTopography's layout).
    #[serde(rename = "nc")]
    NetCdf,
    /// FRT MicroProf `.frt`.
    Frt,
    /// Sensofar `.plux`.
    Plux,
}

impl Format {
    /// Every format, in the order `docs/surface.md` lists them.
    pub const ALL: [Format; 13] = [
        Format::Npy,
        Format::Text,
        Format::X3p,
        Format::Sdf,
        Format::Gwy,
        Format::Sur,
        Format::Nanoscope,
        Format::Ibw,
        Format::Opd,
        Format::Opdx,
        Format::NetCdf,
        Format::Frt,
        Format::Plux,
    ];

    /// The short name (`x3p`, `sdf`, ..., `di` for Nanoscope, `nc`).
    pub fn name(self) -> &'static str {
        match self {
            Format::Npy => "npy",
            Format::Text => "text",
            Format::X3p => "x3p",
            Format::Sdf => "sdf",
            Format::Gwy => "gwy",
            Format::Sur => "sur",
            Format::Nanoscope => "di",
            Format::Ibw => "ibw",
            Format::Opd => "opd",
            Format::Opdx => "opdx",
            Format::NetCdf => "nc",
            Format::Frt => "frt",
            Format::Plux => "plux",
        }
    }

    /// What the format is, for messages.
    pub fn describe(self) -> &'static str {
        match self {
            Format::Npy => "NumPy .npy",
            Format::Text => "text matrix",
            Format::X3p => "X3P (ISO 25178-72)",
            Format::Sdf => "SDF (ISO 25178-71)",
            Format::Gwy => "Gwyddion .gwy",
            Format::Sur => "Digital Surf .sur",
            Format::Nanoscope => "Nanoscope (Bruker/DI)",
            Format::Ibw => "Igor binary wave",
            Format::Opd => "Wyko OPD",
            Format::Opdx => "Dektak OPDx",
            Format::NetCdf => "NetCDF-3",
            Format::Frt => "FRT MicroProf",
            Format::Plux => "Sensofar .plux",
        }
    }

    /// The format of a file name's extension (case-insensitive): `npy`,
    /// `txt`/`csv`/`asc`, `x3p`, `sdf`, `gwy`, `sur`, `di`/`spm`/three
    /// digits (Nanoscope), `ibw`, `opd`, `opdx`, `nc`, `frt`, `plux`.
    pub fn from_extension(ext: &str) -> Option<Format> {
        let e = ext.to_ascii_lowercase();
        Some(match e.as_str() {
            "npy" => Format::Npy,
            "txt" | "csv" | "asc" => Format::Text,
            "x3p" => Format::X3p,
            "sdf" => Format::Sdf,
            "gwy" => Format::Gwy,
            "sur" => Format::Sur,
            "di" | "spm" => Format::Nanoscope,
            d if d.len() == 3 && d.bytes().all(|b| b.is_ascii_digit()) => Format::Nanoscope,
            "ibw" => Format::Ibw,
            "opd" => Format::Opd,
            "opdx" => Format::Opdx,
            "nc" => Format::NetCdf,
            "frt" => Format::Frt,
            "plux" => Format::Plux,
            _ => return None,
        })
    }

    /// The extensions [`Format::from_extension`] knows, for messages.
    pub const EXTENSIONS: &'static str = ".npy, .txt, .csv, .asc, .x3p, .sdf, .gwy, .sur, .di, \
        .spm, .001-.999, .ibw, .opd, .opdx, .nc, .frt, .plux";
}

/// Which channel of a file with several to read.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub enum Channel {
    /// The height channel: the file's first channel whose data are lengths
    /// (or its only one).
    #[default]
    Default,
    /// The channel of this name (exact, else case-insensitive).
    Name(String),
    /// The channel at this index (from 0, in the file's order).
    Index(usize),
}

impl Channel {
    /// `INDEX` (digits) or `NAME`.
    pub fn parse(s: &str) -> Channel {
        match s.trim().parse::<usize>() {
            Ok(i) => Channel::Index(i),
            Err(_) => Channel::Name(s.to_string()),
        }
    }
}

/// A map read from an instrument file.
#[derive(Debug, Clone, PartialEq)]
pub struct Measured {
    /// The file's format.
    pub format: Format,
    /// The channel read.
    pub channel: String,
    /// Every channel the file has (maps only), in the file's order.
    pub channels: Vec<String>,
    /// The unit the instrument wrote the heights in (`m`, `nm`, `um`, ...),
    /// before conversion to metres.
    pub unit: String,
    /// Rows (along y).
    pub rows: usize,
    /// Columns (along x).
    pub cols: usize,
    /// Heights (m), row-major, NaN where a pixel is missing.
    pub heights: Vec<f64>,
    /// Pixel sizes `(dx, dy)` (m) along x (a row) and y (a column), when
    /// the file gives them.
    pub pixel_size: Option<(f64, f64)>,
    /// Whether the file says the map is periodic.
    pub periodic: bool,
}

impl Measured {
    /// Missing pixels (NaN heights).
    pub fn missing(&self) -> usize {
        self.heights.iter().filter(|z| z.is_nan()).count()
    }

    /// Fills every missing pixel from its known neighbours, layer by layer
    /// from the edges of each hole inwards: a pixel of a layer takes the
    /// mean of its 4 neighbours known before that layer. Returns how many
    /// were filled.
    ///
    /// # Errors
    /// [`Error::Invalid`] named `topography` when no pixel is known.
    pub fn fill_missing(&mut self) -> Result<usize> {
        fill::fill(&mut self.heights, self.rows, self.cols)
    }

    /// The heights as a [`HeightMap`].
    ///
    /// # Errors
    /// [`Error::Invalid`] named `topography` when pixels are missing (with
    /// their count and the first one's row and column) or for any reason of
    /// [`HeightMap::new`].
    pub fn into_map(self) -> Result<HeightMap> {
        let n = self.missing();
        if n > 0 {
            let k = self.heights.iter().position(|z| z.is_nan()).unwrap_or(0);
            return Err(Error::invalid(
                "topography",
                format!(
                    "{n} of {} pixels are missing (NaN or masked in the file; the first at row \
                     {}, column {}): refused, or filled from their neighbours with {{fill_missing}}",
                    self.heights.len(),
                    k / self.cols.max(1),
                    k % self.cols.max(1)
                ),
            ));
        }
        HeightMap::new(self.rows, self.cols, self.heights)
    }
}

/// The result of a reader.
pub(crate) type Parsed<T> = std::result::Result<T, Bad>;

/// What is wrong with a file (the reason of the error [`read`] gives).
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Bad {
    reason: String,
    channel: bool,
    /// Beyond the memory: `(rows, cols, needed, available)` (bytes).
    memory: Option<(usize, usize, f64, f64)>,
}

impl Bad {
    /// Content that contradicts the format.
    pub(crate) fn corrupt(reason: impl Into<String>) -> Bad {
        Bad {
            reason: reason.into(),
            channel: false,
            memory: None,
        }
    }

    /// The file ends before what its header describes.
    pub(crate) fn truncated(reason: impl std::fmt::Display) -> Bad {
        Bad::corrupt(format!("truncated: {reason}"))
    }

    /// Not this format at all (the magic is wrong).
    pub(crate) fn magic(expected: &str) -> Bad {
        Bad::corrupt(format!(
            "not this format: the file does not start with {expected}"
        ))
    }

    /// A feature of the format no reader here supports.
    pub(crate) fn unsupported(reason: impl std::fmt::Display) -> Bad {
        Bad::corrupt(format!("unsupported: {reason}"))
    }

    /// The channel asked for does not exist.
    fn channel(reason: String) -> Bad {
        Bad {
            reason,
            channel: true,
            memory: None,
        }
    }

    /// A map of `rows x cols` pixels needs `needed` bytes, more than the
    /// `available`.
    fn memory(rows: usize, cols: usize, needed: f64, available: f64) -> Bad {
        Bad {
            reason: format!("{rows} x {cols} pixels need more memory than is available"),
            channel: false,
            memory: Some((rows, cols, needed, available)),
        }
    }

    /// The crate's error for this reason about a file in `format` (named
    /// `topography`, renamed to the file by [`read`]).
    fn error(self, format: Format) -> Error {
        if let Some((rows, cols, needed, available)) = self.memory {
            return Error::OutOfMemory {
                what: "topography".into(),
                doing: format!(
                    "reading and characterising the {rows} x {cols} map its header declares ({}, \
                     {BYTES_PER_PIXEL} bytes a pixel at most)",
                    format.describe()
                ),
                needed,
                available,
                hint: ": refused before allocating; crop or downsample it".into(),
            };
        }
        if self.channel {
            Error::invalid("{channel}", self.reason)
        } else {
            Error::invalid(
                "topography",
                format!("{} file: {}", format.describe(), self.reason),
            )
        }
    }
}

impl std::fmt::Display for Bad {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.reason)
    }
}

/// The index of the channel `choice` asks for among `names`; `default` for
/// [`Channel::Default`].
pub(crate) fn pick(names: &[String], default: usize, choice: &Channel) -> Parsed<usize> {
    let list = || {
        names
            .iter()
            .enumerate()
            .map(|(k, n)| format!("{k} '{n}'"))
            .collect::<Vec<_>>()
            .join(", ")
    };
    match choice {
        Channel::Default => Ok(default),
        Channel::Index(i) if *i < names.len() => Ok(*i),
        Channel::Index(i) => Err(Bad::channel(format!(
            "no channel {i}; the file has {}",
            list()
        ))),
        Channel::Name(n) => names
            .iter()
            .position(|c| c == n)
            .or_else(|| names.iter().position(|c| c.eq_ignore_ascii_case(n)))
            .ok_or_else(|| Bad::channel(format!("no channel '{n}'; the file has {}", list()))),
    }
}

/// `rows x cols` pixels are plausible ([`dims`]) and fit in the memory
/// available at [`BYTES_PER_PIXEL`] ([`fits`]): what every reader asks
/// before it allocates the heights; the count of pixels.
pub(crate) fn grid(rows: usize, cols: usize) -> Parsed<usize> {
    let n = dims(rows, cols)?;
    fits(rows, cols, BYTES_PER_PIXEL)?;
    Ok(n)
}

/// `Ok` when `rows x cols` pixels at `per_pixel` bytes fit in the memory
/// available ([`crate::study::memory::available`]; always when no bound is
/// known).
pub(crate) fn fits(rows: usize, cols: usize, per_pixel: f64) -> Parsed<()> {
    let needed = rows as f64 * cols as f64 * per_pixel;
    match crate::study::memory::available() {
        Some(have) if needed > have => Err(Bad::memory(rows, cols, needed, have)),
        _ => Ok(()),
    }
}

/// `rows x cols` pixels are plausible: both > 0, their product at most
/// [`MAX_PIXELS`]; the count of pixels.
pub(crate) fn dims(rows: usize, cols: usize) -> Parsed<usize> {
    if rows == 0 || cols == 0 {
        return Err(Bad::corrupt(format!(
            "the header gives {rows} x {cols} pixels"
        )));
    }
    rows.checked_mul(cols)
        .filter(|n| *n <= MAX_PIXELS)
        .ok_or_else(|| {
            Bad::corrupt(format!(
                "the header gives {rows} x {cols} pixels, more than {MAX_PIXELS} (refused before \
                 allocating)"
            ))
        })
}

/// `rows x cols` values of `size` bytes from `data` (exactly that many
/// bytes or more): their bytes.
///
/// A file too short for its header is truncated before it is too large
/// for the memory ([`fits`], checked last).
pub(crate) fn raster(data: &[u8], rows: usize, cols: usize, size: usize) -> Parsed<&[u8]> {
    let n = dims(rows, cols)?;
    let want = n
        .checked_mul(size)
        .ok_or_else(|| Bad::corrupt("the data size overflows"))?;
    let data = data.get(..want).ok_or_else(|| {
        Bad::truncated(format!(
            "{rows} x {cols} values of {size} bytes need {want} bytes, {} are left",
            data.len()
        ))
    })?;
    fits(rows, cols, BYTES_PER_PIXEL)?;
    Ok(data)
}

/// Flips the rows of a row-major `rows x cols` map (row `i` <-> `rows-1-i`).
pub(crate) fn flip_rows(z: &mut [f64], rows: usize, cols: usize) {
    for i in 0..rows / 2 {
        let (a, b) = z.split_at_mut((rows - 1 - i) * cols);
        a[i * cols..(i + 1) * cols].swap_with_slice(&mut b[..cols]);
    }
}

/// The transpose of a row-major `rows x cols` map (`cols x rows`).
pub(crate) fn transpose(z: &[f64], rows: usize, cols: usize) -> Vec<f64> {
    let mut out = vec![0.0; z.len()];
    for i in 0..rows {
        for j in 0..cols {
            out[j * rows + i] = z[i * cols + j];
        }
    }
    out
}

/// Metres per unit of `unit` (see [`units::metres_per`]).
pub(crate) fn metres(unit: &str, what: &str) -> Parsed<f64> {
    units::metres_per(unit, false)
        .ok_or_else(|| Bad::unsupported(format!("{what} unit '{unit}' is no length unit")))
}

/// A positive finite pixel size, or the reason it is not.
pub(crate) fn pixel(d: f64, what: &str) -> Parsed<f64> {
    if d.is_finite() && d > 0.0 {
        Ok(d)
    } else {
        Err(Bad::corrupt(format!(
            "the pixel size along {what} is {d:e}"
        )))
    }
}

/// Parses the bytes of a file in `format`.
///
/// # Errors
/// The reason the bytes are not a readable map of `format` ([`Error::Invalid`]
/// named `topography`), or no channel `channel` (named `{channel}`).
pub fn read_bytes(bytes: &[u8], format: Format, channel: &Channel) -> Result<Measured> {
    let parsed = match format {
        Format::Npy | Format::Text => {
            let map = match format {
                Format::Npy => {
                    let l = crate::surface::npy::layout(bytes)?;
                    fits(l.rows, l.cols, BYTES_PER_PIXEL).map_err(|b| b.error(format))?;
                    crate::surface::npy::parse(bytes)?
                }
                _ => match std::str::from_utf8(bytes) {
                    Ok(t) => crate::surface::text::parse(t)?,
                    Err(_) => return Err(Error::invalid("topography", "not UTF-8 text")),
                },
            };
            if !matches!(channel, Channel::Default | Channel::Index(0)) {
                return Err(Error::invalid(
                    "{channel}",
                    format!("a {} file has one channel", format.describe()),
                ));
            }
            return Ok(Measured {
                format,
                channel: "heights".into(),
                channels: vec!["heights".into()],
                unit: "m".into(),
                rows: map.rows(),
                cols: map.cols(),
                heights: map.into_heights(),
                pixel_size: None,
                periodic: false,
            });
        }
        Format::X3p => x3p::read(bytes, channel),
        Format::Sdf => sdf::read(bytes, channel),
        Format::Gwy => gwy::read(bytes, channel),
        Format::Sur => sur::read(bytes, channel),
        Format::Nanoscope => di::read(bytes, channel),
        Format::Ibw => ibw::read(bytes, channel),
        Format::Opd => opd::read(bytes, channel),
        Format::Opdx => opdx::read(bytes, channel),
        Format::NetCdf => nc::read(bytes, channel),
        Format::Frt => frt::read(bytes, channel),
        Format::Plux => plux::read(bytes, channel),
    };
    parsed.map_err(|b| b.error(format))
}

/// The format of `path` by its extension.
///
/// # Errors
/// [`Error::Invalid`] naming the file for an unknown extension.
pub fn format_of(path: &Path) -> Result<Format> {
    let ext = path
        .extension()
        .and_then(|e| e.to_str())
        .unwrap_or_default();
    Format::from_extension(ext).ok_or_else(|| {
        Error::invalid(
            path.display().to_string(),
            format!("unknown extension '{ext}': expected {}", Format::EXTENSIONS),
        )
    })
}

/// Reads the map in `path` by its extension ([`format_of`]); errors about
/// the content name the file. The file is memory-mapped; the memory a map
/// needs is checked against its header's dimensions at [`BYTES_PER_PIXEL`]
/// before the heights are allocated (a text map, which declares none, by
/// its size: [`crate::study::memory::check_map`]).
///
/// # Errors
/// [`Error::Invalid`] naming the file (unreadable, unknown extension, bad
/// content with the format and the reason), [`Error::OutOfMemory`] naming it
/// beyond the memory available, `{channel}` for a channel the file does not
/// have.
pub fn read(path: &Path, channel: &Channel) -> Result<Measured> {
    let shown = path.display().to_string();
    let format = format_of(path)?;
    if format == Format::Text {
        crate::study::memory::check_map(path)?;
    }
    let bytes = mapped::open(path, &shown)?;
    read_bytes(&bytes, format, channel).map_err(|e| match e.field() {
        Some("topography") => e.renamed(&shown),
        _ => e,
    })
}

/// Reads the `.npy` map in `path` into the one buffer the characterisation
/// uses: a float64 map in the machine's byte order (what `numpy.save`
/// writes) is the memory-mapped file itself, validated in one pass and
/// never copied ([`HeightMap::is_shared`]); a float32 or byte-swapped map
/// is decoded into one `Vec`. Errors about the content name the file.
///
/// # Errors
/// As [`read`].
pub fn read_npy(path: &Path) -> Result<HeightMap> {
    let shown = path.display().to_string();
    let bytes = mapped::open(path, &shown)?;
    mapped::npy_map(&bytes).map_err(|e| match e.field() {
        Some("topography") => e.renamed(&shown),
        _ => e,
    })
}
