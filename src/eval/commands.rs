//! The command policy: which programs of the host a script may run (EXTE).
//!
//! Running a program reaches everything the file policy guards and more,
//! so the library runs none by default and a host opts in, for every
//! program or for programs it names. A program is named by the first word
//! of the command as the script writes it (`md5sum`, `/usr/bin/bc`): the
//! command is never given to a shell, so the rest of it can only be the
//! program's arguments.

use crate::error::{Error, ErrorKind, Result};

/// Which programs a script may run. The library allows none by default;
/// the CLI too, unless `--allow-commands` or `--allow-command NAME`.
#[derive(Debug, Clone, Default)]
pub enum CommandPolicy {
    #[default]
    Nothing,
    /// Only these programs, as the script names them.
    Only(Vec<String>),
    Anything,
}

impl CommandPolicy {
    /// Whether the script may run `program`, or the refusal.
    pub fn check(&self, program: &str) -> Result<()> {
        let allowed = match self {
            CommandPolicy::Anything => true,
            CommandPolicy::Only(names) => names.iter().any(|n| n == program),
            CommandPolicy::Nothing => false,
        };
        if allowed {
            return Ok(());
        }
        let how = match self {
            CommandPolicy::Only(_) => "it is not among the programs this run may start",
            _ => "this run may not start programs",
        };
        Err(Error::new(ErrorKind::Denied, format!("running '{}' is not allowed: {}", program, how))
            .note("the host allows commands (gibi: --allow-command NAME for one program, --allow-commands for any)"))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn nothing_runs_unless_allowed() {
        assert_eq!(CommandPolicy::default().check("echo").unwrap_err().kind, ErrorKind::Denied);
        let only = CommandPolicy::Only(vec!["md5sum".into()]);
        assert!(only.check("md5sum").is_ok());
        assert!(only.check("/usr/bin/md5sum").is_err());
        assert!(CommandPolicy::Anything.check("bc").is_ok());
    }
}
