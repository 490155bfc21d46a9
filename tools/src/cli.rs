//! The command-line front the two binaries share, so that `obj2rs` and
//! `png2rs` read their arguments alike: options before or after the input,
//! `--opt VALUE` or `--opt=VALUE`, `-` for standard input, `--out FILE` or
//! standard output, errors naming the option, and the same exit statuses
//! (0 done, 1 the input could not be converted, 2 bad arguments).
//!
//! ```
//! use microraster_tools::cli::{Arg, Args};
//! let argv: Vec<String> = ["in.png", "--name=icon", "--out", "icon.rs"].map(String::from).into();
//! let mut args = Args::new(&argv);
//! assert!(matches!(args.next_arg(), Ok(Some(Arg::Positional("in.png")))));
//! assert!(matches!(args.next_arg(), Ok(Some(Arg::Opt("--name")))));
//! assert_eq!(args.value("--name").ok(), Some("icon"));
//! assert!(matches!(args.next_arg(), Ok(Some(Arg::Opt("--out")))));
//! assert_eq!(args.value("--out").ok(), Some("icon.rs"));
//! assert!(matches!(args.next_arg(), Ok(None)));
//! ```

use std::io::{Read, Write};
use std::path::Path;
use std::process::ExitCode;

/// Why a run failed, which decides the exit status.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Failure {
    /// Bad arguments: the message, the usage line and a pointer to
    /// `--help` on stderr; exit status 2.
    Usage(String),
    /// The input could not be read, converted or written: the message on
    /// stderr; exit status 1.
    Input(String),
}

/// One command-line argument.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Arg<'a> {
    /// An option (`--name`, `-h`), without an `=VALUE` part: take that, or
    /// the next argument, with [`Args::value`].
    Opt(&'a str),
    /// Anything else (`-` included: standard input).
    Positional(&'a str),
}

/// The arguments, read one at a time.
#[derive(Debug, Clone)]
pub struct Args<'a> {
    rest: std::slice::Iter<'a, String>,
    /// The `VALUE` of the last `--opt=VALUE`, not yet taken.
    inline: Option<&'a str>,
    /// The option it belongs to.
    last: &'a str,
}

impl<'a> Args<'a> {
    /// Reads `args` (without the program name).
    pub fn new(args: &'a [String]) -> Self {
        Args { rest: args.iter(), inline: None, last: "" }
    }

    /// The next argument, `None` at the end.
    ///
    /// # Errors
    /// An `=VALUE` given to the previous option but not taken (a flag such as
    /// `--plain=yes`).
    pub fn next_arg(&mut self) -> Result<Option<Arg<'a>>, Failure> {
        if self.inline.take().is_some() {
            return Err(Failure::Usage(format!("{} takes no value", self.last)));
        }
        let Some(a) = self.rest.next() else { return Ok(None) };
        if a == "-" || !a.starts_with('-') {
            return Ok(Some(Arg::Positional(a)));
        }
        let (opt, value) = a.split_once('=').map_or((a.as_str(), None), |(o, v)| (o, Some(v)));
        (self.inline, self.last) = (value, opt);
        Ok(Some(Arg::Opt(opt)))
    }

    /// The value of option `opt`: its `=VALUE`, else the next argument.
    ///
    /// # Errors
    /// No next argument, or one that is itself an option (`--name --out
    /// x.rs` is a forgotten name, not a name `--out`).
    pub fn value(&mut self, opt: &str) -> Result<&'a str, Failure> {
        if let Some(v) = self.inline.take() {
            return Ok(v);
        }
        match self.rest.clone().next() {
            Some(v) if v == "-" || !v.starts_with('-') => {
                self.rest.next();
                Ok(v)
            }
            Some(v) => Err(Failure::Usage(format!("{opt} needs a value (found the option `{v}`)"))),
            None => Err(Failure::Usage(format!("{opt} needs a value"))),
        }
    }
}

/// Runs a converter's `run` on the process arguments and turns its result
/// into the exit status, printing failures as `tool: message` on stderr
/// (with `usage` and a pointer to `--help` after a usage error).
pub fn main(tool: &str, usage: &str, run: impl FnOnce(&[String]) -> Result<(), Failure>) -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    match run(&args) {
        Ok(()) => ExitCode::SUCCESS,
        Err(Failure::Usage(msg)) => {
            report(tool, &format!("{msg}\n{usage}\nRun `{tool} --help` for what each option does."));
            ExitCode::from(2)
        }
        Err(Failure::Input(msg)) => {
            report(tool, &msg);
            ExitCode::FAILURE
        }
    }
}

/// Writes `tool: msg` to stderr, ignoring failure (a broken stderr must not
/// panic).
pub fn report(tool: &str, msg: &str) {
    let _ = writeln!(std::io::stderr(), "{tool}: {msg}");
}

/// Writes `text` to stdout (`--help`), ignoring failure.
pub fn print(text: &str) {
    let _ = std::io::stdout().write_all(text.as_bytes());
}

/// An input read by [`read_input`].
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Input {
    /// The bytes.
    pub bytes: Vec<u8>,
    /// The file name (not the path) for the generated header comment, so the
    /// output does not depend on where the checkout lives; `<stdin>` for `-`.
    pub source: String,
    /// How messages name it: the path as given, or `<stdin>`.
    pub shown: String,
}

/// Reads `path`, or standard input for `-`.
///
/// # Errors
/// The file cannot be read ([`Failure::Input`], naming it).
pub fn read_input(path: &str) -> Result<Input, Failure> {
    let mut bytes = Vec::new();
    if path == "-" {
        let shown = "<stdin>".to_string();
        std::io::stdin().read_to_end(&mut bytes).map_err(|e| Failure::Input(format!("{shown}: {e}")))?;
        return Ok(Input { bytes, source: shown.clone(), shown });
    }
    let bytes = std::fs::read(path).map_err(|e| Failure::Input(format!("{path}: {e}")))?;
    let source = Path::new(path).file_name().map_or_else(|| path.to_string(), |f| f.to_string_lossy().into());
    Ok(Input { bytes, source, shown: path.to_string() })
}

/// Writes `text` to the file `out`, or to standard output without one.
///
/// # Errors
/// The file or stdout cannot be written ([`Failure::Input`], naming it).
pub fn write_output(out: Option<&str>, text: &str) -> Result<(), Failure> {
    match out {
        Some(path) => std::fs::write(path, text).map_err(|e| Failure::Input(format!("{path}: {e}"))),
        None => {
            let mut stdout = std::io::stdout().lock();
            stdout
                .write_all(text.as_bytes())
                .and_then(|()| stdout.flush())
                .map_err(|e| Failure::Input(format!("stdout: {e}")))
        }
    }
}

/// `value` unless the option was already given (`--name a --name b` is a
/// mistake, not the last one winning).
///
/// # Errors
/// The option was already set.
pub fn once<T>(slot: &mut Option<T>, opt: &str, value: T) -> Result<(), Failure> {
    if slot.replace(value).is_some() {
        return Err(Failure::Usage(format!("{opt} given twice")));
    }
    Ok(())
}
