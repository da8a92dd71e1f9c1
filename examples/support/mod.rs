//! What the examples share: where they write their files, and the library's SVG line chart.

#![allow(dead_code)]

use std::fs;
use std::path::PathBuf;

pub use dirac::plot::{Chart, Series};

/// The folder examples write into: `target/dirac-examples`, created if needed.
pub fn output_dir() -> std::io::Result<PathBuf> {
    let dir = PathBuf::from("target/dirac-examples");
    fs::create_dir_all(&dir)?;
    Ok(dir)
}
