//! A learner's coordinator: `coordinate(outputs, p)` answers the name of
//! the behaviour that drives, or a command or vector of its own.

use kinolab_script::{Dynamic, Script, ScriptError};
use kinolab_world::Command;
use kinolab_world::sensors::Percepts;

use super::{Decision, Responses, Trace};
use crate::Drive;
use crate::script::{COORDINATE, ScriptCall, percepts, response, response_value};

/// The compiled coordinator, its last call, and the error that stopped it.
#[derive(Debug, Clone, PartialEq)]
pub struct ScriptState {
    script: Option<Script>,
    pub call: Option<ScriptCall>,
    pub failed: Option<ScriptError>,
}

impl ScriptState {
    pub fn new(source: &str) -> Self {
        match Script::compile(source, COORDINATE) {
            Ok(script) => Self {
                script: Some(script),
                call: None,
                failed: None,
            },
            Err(e) => Self {
                script: None,
                call: None,
                failed: Some(e),
            },
        }
    }

    /// This step's decision; stands still once the script has failed.
    pub fn decide(&mut self, r: &Responses<'_>, p: &Percepts, drive: &Drive) -> Decision {
        let still = Decision {
            command: Command::unicycle(0.0, 0.0),
            in_control: None,
            trace: Trace::Script { chose: None },
        };
        let Some(script) = self.script.as_mut().filter(|_| self.failed.is_none()) else {
            return still;
        };
        let outputs = kinolab_script::value::map(
            r.behaviours
                .iter()
                .zip(r.responses)
                .map(|(b, resp)| (b.name.as_str(), response_value(resp.as_ref()))),
        );
        let answer = script
            .call(vec![outputs, percepts(p)], p.time)
            .and_then(|call| {
                let decision =
                    choose(&call.value, r, p.time, drive).map_err(|e| script.place(e))?;
                self.call = Some(ScriptCall {
                    who: "coordinator".into(),
                    returned: kinolab_script::value::describe(&call.value),
                    output: call.output,
                });
                Ok(decision)
            });
        answer.unwrap_or_else(|e| {
            self.failed = Some(e);
            still
        })
    }
}

/// The decision a coordinator's answer makes: a behaviour's name chooses
/// that behaviour's response; otherwise the answer is the response.
fn choose(
    value: &Dynamic,
    r: &Responses<'_>,
    t: f64,
    drive: &Drive,
) -> Result<Decision, ScriptError> {
    if let Some(name) = kinolab_script::value::text(value) {
        let i = r.index(&name).ok_or_else(|| {
            let names: Vec<String> = r
                .behaviours
                .iter()
                .map(|b| format!("\"{}\"", b.name))
                .collect();
            ScriptError::shape(
                COORDINATE,
                &format!("the name of one of the behaviours ({})", names.join(", ")),
                &format!("\"{name}\""),
                t,
            )
        })?;
        let command = r.responses[i]
            .as_ref()
            .map_or(Command::unicycle(0.0, 0.0), |resp| drive.command(resp));
        return Ok(Decision {
            command,
            in_control: Some(i),
            trace: Trace::Script { chose: Some(name) },
        });
    }
    let command = response(value, COORDINATE, t)?
        .map_or(Command::unicycle(0.0, 0.0), |resp| drive.command(&resp));
    Ok(Decision {
        command,
        in_control: None,
        trace: Trace::Script { chose: None },
    })
}
