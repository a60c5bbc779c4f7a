//! The file-access policy: where a script may read and write.
//!
//! A path is checked on its *real* location: every symbolic link in it is
//! resolved before the check, so `link/x` with `link -> /elsewhere` is
//! outside the directory even though its text is not. The opener then
//! refuses to follow a link in the final component (`io::read_file`,
//! `io::write_file`), so a link put in place after the check is not
//! followed either.

use crate::error::{Error, ErrorKind, Result};
use std::path::{Component, Path, PathBuf};

/// Where a script may read or write files. The library allows nothing by
/// default; the CLI allows its working directory.
#[derive(Debug, Clone)]
pub enum FilePolicy {
    Nothing,
    /// Only inside this directory, links resolved.
    Under(PathBuf),
    Anywhere,
}

impl FilePolicy {
    /// The real path of a file a script wants to read, or the refusal.
    pub fn check_read(&self, path: &str) -> Result<PathBuf> {
        self.resolve(path, "read")
    }

    /// The real path of a file a script wants to write (its directories
    /// may not exist yet), or the refusal.
    pub fn check_write(&self, path: &str) -> Result<PathBuf> {
        self.resolve(path, "write")
    }

    /// `path` as it should be shown to the user: relative to the allowed
    /// directory (or to the working directory) when inside it.
    pub fn display(&self, path: &Path) -> String {
        let base = match self {
            FilePolicy::Under(root) => root.canonicalize().ok(),
            _ => std::env::current_dir().ok().and_then(|d| d.canonicalize().ok()),
        };
        let real = path.canonicalize().unwrap_or_else(|_| path.to_path_buf());
        match base.as_deref().and_then(|b| real.strip_prefix(b).ok()) {
            Some(rel) => rel.display().to_string(),
            None => path.display().to_string(),
        }
    }

    fn resolve(&self, path: &str, verb: &str) -> Result<PathBuf> {
        let p = Path::new(path);
        let root = match self {
            FilePolicy::Anywhere => return Ok(p.to_path_buf()),
            FilePolicy::Nothing => {
                return Err(denied(format!("file access to '{}' is not allowed by the host application", path)))
            }
            FilePolicy::Under(root) => root,
        };
        let outside = |how: &str| {
            denied(format!("'{}' is outside the directory this run may use ({}){}", path, root.display(), how))
        };
        if p.components().any(|c| matches!(c, Component::ParentDir)) {
            return Err(outside(""));
        }
        let real_root = root.canonicalize().map_err(|e| {
            denied(format!("the directory this run may use ({}) cannot be resolved: {}", root.display(), e))
        })?;
        let full = if p.is_absolute() { p.to_path_buf() } else { root.join(p) };
        if !(full.starts_with(root) || full.starts_with(&real_root)) {
            return Err(outside(""));
        }
        // The deepest part of the path that exists is resolved (links
        // followed); the rest does not exist yet, so it holds no link.
        let mut existing = full.as_path();
        let mut missing: Vec<&std::ffi::OsStr> = Vec::new();
        while existing.symlink_metadata().is_err() {
            match (existing.file_name(), existing.parent()) {
                (Some(name), Some(parent)) => {
                    missing.push(name);
                    existing = parent;
                }
                _ => return Err(outside("")),
            }
        }
        // A link whose target does not exist cannot be resolved: where it
        // leads cannot be checked, so it is refused.
        let mut real = existing.canonicalize().map_err(|e| {
            denied(format!("cannot {} '{}': a symbolic link on its way leads nowhere ({})", verb, path, e))
        })?;
        if !real.starts_with(&real_root) {
            return Err(outside(" through a symbolic link"));
        }
        real.extend(missing.iter().rev());
        Ok(real)
    }
}

fn denied(msg: String) -> Error {
    Error::new(ErrorKind::Denied, msg)
}

#[cfg(all(test, unix))]
mod tests {
    use super::*;
    use std::os::unix::fs::symlink;

    fn scratch(name: &str) -> (PathBuf, PathBuf) {
        let base = std::env::temp_dir().join(format!("gibi-files-{}-{}", name, std::process::id()));
        let _ = std::fs::remove_dir_all(&base);
        let (root, outside) = (base.join("root"), base.join("outside"));
        std::fs::create_dir_all(&root).unwrap();
        std::fs::create_dir_all(&outside).unwrap();
        (root, outside)
    }

    #[test]
    fn links_are_resolved_before_the_check() {
        let (root, outside) = scratch("links");
        std::fs::write(outside.join("secret"), "x").unwrap();
        std::fs::create_dir(root.join("sub")).unwrap();
        std::fs::write(root.join("sub/mesh.msh"), "x").unwrap();
        symlink(&outside, root.join("away")).unwrap();
        symlink(outside.join("secret"), root.join("p.msh")).unwrap();
        symlink(root.join("sub/mesh.msh"), root.join("inside.msh")).unwrap();
        symlink(root.join("sub"), root.join("subdir")).unwrap();
        symlink(outside.join("none"), root.join("dangling")).unwrap();
        let pol = FilePolicy::Under(root.clone());
        let real_root = root.canonicalize().unwrap();
        for (path, write) in [("away/x.vtu", true), ("away/new/x.vtu", true), ("p.msh", false), ("p.msh", true)] {
            let r = if write { pol.check_write(path) } else { pol.check_read(path) };
            let e = r.expect_err(path);
            assert_eq!(e.kind, ErrorKind::Denied, "{}", path);
            assert!(e.message.contains("through a symbolic link"), "{}", e.message);
        }
        // A dangling link is refused: its target is unknown.
        assert!(pol.check_write("dangling").is_err());
        // Links that stay inside are fine, and the real path is returned.
        assert_eq!(pol.check_read("inside.msh").unwrap(), real_root.join("sub/mesh.msh"));
        assert_eq!(pol.check_write("subdir/new/a.vtu").unwrap(), real_root.join("sub/new/a.vtu"));
        assert_eq!(pol.check_write("out/a.vtu").unwrap(), real_root.join("out/a.vtu"));
        // The allowed directory may itself be reached through a link.
        let alias = outside.join("alias");
        symlink(&root, &alias).unwrap();
        assert_eq!(FilePolicy::Under(alias).check_write("a.svg").unwrap(), real_root.join("a.svg"));
        assert_eq!(pol.display(&real_root.join("sub/mesh.msh")), "sub/mesh.msh");
    }

    #[test]
    fn text_outside_the_directory_is_refused() {
        let (root, _) = scratch("text");
        let pol = FilePolicy::Under(root.clone());
        assert_eq!(pol.check_write("../a.txt").unwrap_err().kind, ErrorKind::Denied);
        assert_eq!(pol.check_write("/etc/passwd").unwrap_err().kind, ErrorKind::Denied);
        assert!(pol.check_write(root.join("a.txt").to_str().unwrap()).is_ok());
        assert_eq!(FilePolicy::Nothing.check_read("a.txt").unwrap_err().kind, ErrorKind::Denied);
    }
}
