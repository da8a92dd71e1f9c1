//! Packing a built library and its description into an `.fmu` file.

use std::io::Write as _;
use std::path::{Path, PathBuf};
use std::process::Command;

use zip::write::SimpleFileOptions;

use crate::Storage;
use crate::nalgebra::DefaultAllocator;

use super::variables::{self, DescriptionError};
use super::{Fmu, Version};

/// Why an FMU could not be written.
#[derive(Debug, thiserror::Error)]
pub enum FmuError {
    /// The model cannot be described.
    #[error(transparent)]
    Description(#[from] DescriptionError),
    /// A file could not be read or written.
    #[error("{path}: {source}")]
    Io {
        /// The file.
        path: PathBuf,
        /// The failure.
        source: std::io::Error,
    },
    /// The zip could not be written.
    #[error("writing {path}: {source}")]
    Zip {
        /// The FMU file.
        path: PathBuf,
        /// The failure.
        source: zip::result::ZipError,
    },
    /// `cargo build` failed or built no shared library.
    #[error("cargo build {args}: {reason}")]
    Build {
        /// Its arguments.
        args: String,
        /// What went wrong.
        reason: String,
    },
    /// FMI names no binary directory for this platform.
    #[error("FMI names no binary directory for {0}")]
    Platform(String),
    /// The FMU's model could not be made ([`Fmu::model`]).
    #[error("the FMU's model could not be made: {0}")]
    Model(String),
}

/// The FMI version's name for this platform's binary directory, and its shared libraries'
/// extension: `x86_64-linux` in FMI 3.0, `linux64` in FMI 2.0.
fn platform(version: Version) -> Result<(String, &'static str), FmuError> {
    let unknown = |what: &str| FmuError::Platform(what.to_string());
    let (os, arch) = (std::env::consts::OS, std::env::consts::ARCH);
    let name = match version {
        Version::Fmi3 => {
            let os = match os {
                "linux" => "linux",
                "macos" => "darwin",
                "windows" => "windows",
                other => return Err(unknown(other)),
            };
            let arch = match arch {
                "x86_64" | "aarch64" | "x86" => arch,
                other => return Err(unknown(other)),
            };
            format!("{arch}-{os}")
        }
        Version::Fmi2 => {
            let os = match os {
                "linux" => "linux",
                "macos" => "darwin",
                "windows" => "win",
                other => return Err(unknown(other)),
            };
            let bits = match arch {
                "x86_64" | "aarch64" => "64",
                "x86" => "32",
                other => return Err(unknown(other)),
            };
            format!("{os}{bits}")
        }
    };
    Ok((name, std::env::consts::DLL_EXTENSION))
}

/// Writes FMU `F` to `out`: its `modelDescription.xml` for `version` and `library`, the shared
/// library of a crate that invokes [`export_fmu!`](crate::export_fmu) for `F`, built for this
/// platform (it implements both versions). Every [`Export`](super::Export) model is an FMU.
pub fn write_fmu<F: Fmu>(library: &Path, out: &Path, version: Version) -> Result<(), FmuError>
where
    DefaultAllocator: Storage<F::Model>,
{
    write::<F>(library, None, out, version)
}

/// [`write_fmu`], with every file of the folder `resources` (and of its subfolders) packed in
/// the FMU's `resources/`, where [`Fmu::model`] reads them: it is given this folder to describe
/// the model here, and the importer's copy of it in each instance.
pub fn write_fmu_with_resources<F: Fmu>(
    library: &Path,
    resources: &Path,
    out: &Path,
    version: Version,
) -> Result<(), FmuError>
where
    DefaultAllocator: Storage<F::Model>,
{
    write::<F>(library, Some(resources), out, version)
}

fn write<F: Fmu>(
    library: &Path,
    resources: Option<&Path>,
    out: &Path,
    version: Version,
) -> Result<(), FmuError>
where
    DefaultAllocator: Storage<F::Model>,
{
    let start = F::model(resources).map_err(|e| FmuError::Model(e.to_string()))?;
    let (description, _) = variables::description::<F>(&start, version)?;
    drop(start);
    let files = match resources {
        Some(dir) => resource_files(dir)?,
        None => Vec::new(),
    };
    let (platform, extension) = platform(version)?;
    let binary = std::fs::read(library).map_err(|source| FmuError::Io { path: library.into(), source })?;
    if let Some(dir) = out.parent().filter(|d| !d.as_os_str().is_empty()) {
        std::fs::create_dir_all(dir).map_err(|source| FmuError::Io { path: dir.into(), source })?;
    }
    let io = |source| FmuError::Io { path: out.into(), source };
    let zipped = |source| FmuError::Zip { path: out.into(), source };
    let file = std::fs::File::create(out).map_err(io)?;
    let mut zip = zip::ZipWriter::new(file);
    let options = SimpleFileOptions::default().compression_method(zip::CompressionMethod::Stored);
    zip.start_file("modelDescription.xml", options).map_err(zipped)?;
    zip.write_all(description.as_bytes()).map_err(io)?;
    let name = format!("binaries/{platform}/{}.{extension}", F::IDENTIFIER);
    zip.start_file(name, options.unix_permissions(0o755)).map_err(zipped)?;
    zip.write_all(&binary).map_err(io)?;
    for (name, path) in files {
        let bytes = std::fs::read(&path).map_err(|source| FmuError::Io { path, source })?;
        zip.start_file(format!("resources/{name}"), options).map_err(zipped)?;
        zip.write_all(&bytes).map_err(io)?;
    }
    zip.finish().map_err(zipped)?;
    Ok(())
}

/// Every file under `dir`, with its path relative to `dir` in `/`-separated form, sorted.
fn resource_files(dir: &Path) -> Result<Vec<(String, PathBuf)>, FmuError> {
    let mut files = Vec::new();
    let mut folders = vec![(String::new(), dir.to_path_buf())];
    while let Some((prefix, folder)) = folders.pop() {
        let entries =
            std::fs::read_dir(&folder).map_err(|source| FmuError::Io { path: folder.clone(), source })?;
        for entry in entries {
            let entry = entry.map_err(|source| FmuError::Io { path: folder.clone(), source })?;
            let path = entry.path();
            let name = format!("{prefix}{}", entry.file_name().to_string_lossy());
            let kind = entry.file_type().map_err(|source| FmuError::Io { path: path.clone(), source })?;
            if kind.is_dir() {
                folders.push((format!("{name}/"), path));
            } else {
                files.push((name, path));
            }
        }
    }
    files.sort();
    Ok(files)
}

/// Runs `cargo build` with `args` (for example `["--release", "--lib"]` or
/// `["--example", "fmu_paper_chain"]`), takes the shared library it builds, and writes FMU `F`
/// for `version` to `out` ([`write_fmu`]). Returns the library's path.
///
/// Called from a program that `cargo run` started, it runs the same cargo.
pub fn build<F: Fmu>(args: &[&str], out: &Path, version: Version) -> Result<PathBuf, FmuError>
where
    DefaultAllocator: Storage<F::Model>,
{
    let library = cargo_build(args)?;
    write::<F>(&library, None, out, version)?;
    Ok(library)
}

/// [`build`], with the files of `resources` packed as [`write_fmu_with_resources`] packs them.
pub fn build_with_resources<F: Fmu>(
    args: &[&str],
    resources: &Path,
    out: &Path,
    version: Version,
) -> Result<PathBuf, FmuError>
where
    DefaultAllocator: Storage<F::Model>,
{
    let library = cargo_build(args)?;
    write::<F>(&library, Some(resources), out, version)?;
    Ok(library)
}

/// Runs `cargo build` with `args`; the shared library it built.
fn cargo_build(args: &[&str]) -> Result<PathBuf, FmuError> {
    let cargo = std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into());
    let joined = args.join(" ");
    let failed = |reason: String| FmuError::Build { args: joined.clone(), reason };
    let output = Command::new(cargo)
        .arg("build")
        .args(args)
        .arg("--message-format=json-render-diagnostics")
        .stderr(std::process::Stdio::inherit())
        .output()
        .map_err(|e| failed(format!("cargo did not run: {e}")))?;
    if !output.status.success() {
        return Err(failed(format!("it exited with {}", output.status)));
    }
    let stdout = String::from_utf8_lossy(&output.stdout);
    shared_library(&stdout).ok_or_else(|| failed("it built no cdylib".to_string()))
}

/// The last `cdylib` among cargo's JSON messages.
fn shared_library(messages: &str) -> Option<PathBuf> {
    let extension = format!(".{}", std::env::consts::DLL_EXTENSION);
    messages
        .lines()
        .rev()
        .filter(|line| line.contains("\"reason\":\"compiler-artifact\"") && line.contains("\"cdylib\""))
        .find_map(|line| {
            let start = line.find("\"filenames\":[")? + "\"filenames\":[".len();
            let list = &line[start..start + line[start..].find(']')?];
            list.split(',')
                .map(|quoted| quoted.trim().trim_matches('"').replace("\\\\", "\\"))
                .find(|path| path.ends_with(&extension))
        })
        .map(PathBuf::from)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[cfg(target_os = "linux")]
    #[test]
    fn the_shared_library_is_found_among_cargos_messages() {
        let messages = concat!(
            r#"{"reason":"compiler-artifact","target":{"crate_types":["lib"]},"filenames":["/t/libdep.rlib"]}"#,
            "\n",
            r#"{"reason":"compiler-artifact","target":{"kind":["cdylib"],"crate_types":["cdylib"]},"#,
            r#""filenames":["/t/debug/examples/libfmu_chain.so"],"executable":null}"#,
            "\n",
            r#"{"reason":"build-finished","success":true}"#,
        );
        assert_eq!(shared_library(messages), Some(PathBuf::from("/t/debug/examples/libfmu_chain.so")));
        assert_eq!(shared_library(r#"{"reason":"build-finished","success":true}"#), None);
    }
}
