//! `kinolab`: the lab's core on the command line.
//!
//! Every call prints exactly one JSON document on stdout. Bad input exits
//! with status 2 and one line on stderr naming the file or option and the
//! field; nothing ever prints a panic or a backtrace.
//!
//! The commands are a host of the lab's one API (`kinolab-api`): each turns
//! its options and files into a request and prints the report, the same
//! JSON the JavaScript package returns. Commands are grouped as the lab
//! teaches: bodies ([`wheels`], [`mechanism`], [`legs`]), minds
//! ([`control`], [`behaviours`], [`plans`]), communication ([`components`])
//! and teaching ([`teach`]).

mod args;
mod ask;
mod behaviours;
mod components;
mod control;
mod input;
mod legs;
mod mechanism;
mod output;
mod plans;
mod script;
mod teach;
mod wheels;

use std::process::ExitCode;

use clap::{Parser, Subcommand};
use serde_json::Value;

/// The Kinolab robotics lab's core, scriptable. Prints one JSON document per call.
#[derive(Debug, Parser)]
#[command(name = "kinolab", version, about, long_about = None)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Debug, Subcommand)]
enum Command {
    #[command(flatten)]
    Legs(legs::Command),
    #[command(flatten)]
    Wheels(wheels::Command),
    #[command(flatten)]
    Control(control::Command),
    #[command(flatten)]
    Mechanism(mechanism::Command),
    #[command(flatten)]
    Behaviours(behaviours::Command),
    #[command(flatten)]
    Plans(plans::Command),
    #[command(flatten)]
    Components(components::Command),
    #[command(flatten)]
    Teach(teach::Command),
    /// A model as URDF for ROS and its tools, printed; what URDF cannot say goes to stderr.
    ExportUrdf {
        /// A model file (`*.model.json`), or `catalogue:<id>`.
        model: std::path::PathBuf,
    },
    /// Graded code exercises: list them, check a learner's script, grade a class.
    Script {
        #[command(subcommand)]
        command: script::Command,
    },
}

/// What a command prints: one JSON document, or text (CSV).
enum Printed {
    Json(Value),
    Text(String),
}

/// A failure reported as one line on stderr.
struct Failure(String);

fn run(command: Command) -> Result<Printed, Failure> {
    match command {
        Command::Legs(c) => legs::run(c),
        Command::Wheels(c) => wheels::run(c),
        Command::Control(c) => control::run(c),
        Command::Mechanism(c) => mechanism::run(c),
        Command::Behaviours(c) => behaviours::run(c),
        Command::Plans(c) => plans::run(c),
        Command::Components(c) => components::run(c),
        Command::Teach(c) => teach::run(c),
        Command::Script { command } => return script::run(command),
        Command::ExportUrdf { model } => return mechanism::export_urdf(&model),
    }
    .map(Printed::Json)
}

/// Clap's complaint as one line: what is wrong and which option, without
/// the usage block that follows it.
fn usage_error(e: &clap::Error) -> String {
    use clap::error::ErrorKind;
    if matches!(
        e.kind(),
        ErrorKind::MissingSubcommand | ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand
    ) {
        return "no command given; `kinolab --help` lists them".into();
    }
    let text = e.to_string();
    let parts: Vec<&str> = text
        .lines()
        .map(str::trim)
        .take_while(|l| !l.starts_with("Usage:"))
        .filter(|l| !l.is_empty() && !l.starts_with("For more information"))
        .collect();
    parts.join(" ").trim_start_matches("error: ").to_owned()
}

fn main() -> ExitCode {
    let cli = match Cli::try_parse() {
        Ok(cli) => cli,
        Err(e) if e.use_stderr() => return output::fail(&usage_error(&e)),
        Err(e) => {
            // --help and --version go to stdout as clap formats them.
            let _ = e.print();
            return ExitCode::SUCCESS;
        }
    };
    match run(cli.command) {
        Ok(Printed::Json(value)) => output::print(&value),
        Ok(Printed::Text(text)) => output::print_text(&text),
        Err(Failure(message)) => output::fail(&message),
    }
}
