//! "Why did this port get nothing?": the runtime saw every message, so it
//! can say which of the usual reasons it was.

use serde::Serialize;

use crate::pattern::Pattern;
use crate::runtime::Runtime;
use crate::trace::Status;

/// The answer, with a code for programs and a sentence for people.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Why {
    /// `received`, `one-way` (a connected send port), `no-such-port`, `incompatible`, `not-connected`,
    /// `not-subscribed`, `event-not-activated`, `cancelled`, `lost`,
    /// `prescale`, `server-not-running`, `in-flight`, `nothing-sent`.
    pub reason: &'static str,
    pub message: String,
}

fn why(reason: &'static str, message: String) -> Why {
    Why { reason, message }
}

impl Runtime {
    /// Why port `name` (`component.port`) got nothing so far.
    pub fn why_nothing(&self, name: &str) -> Why {
        let Ok((c, p)) = self.port_ref(name) else {
            return why("no-such-port", format!("there is no port `{name}`"));
        };
        let port = &self.slots[c].ports[p];
        let st = port.stats;
        if st.received > 0 {
            return why(
                "received",
                format!("`{name}` did get {} messages", st.received),
            );
        }
        if port.spec.pattern == Pattern::Send && port.wire.is_some() {
            return why(
                "one-way",
                format!(
                    "send is one-way: `{name}` sends ({} so far) and nothing ever comes back",
                    st.sent
                ),
            );
        }
        let Some(wire) = &port.wire else {
            return match &port.refusal {
                Some(r) => why("incompatible", format!("its connection was refused: {r}")),
                None => why(
                    "not-connected",
                    format!("`{name}` is not connected to any service"),
                ),
            };
        };
        let server = &self.slots[wire.service.0];
        let pattern = port.spec.pattern;
        let is_push = matches!(pattern, Pattern::PushNewest | Pattern::PushTimed);
        if st.cancelled > 0 {
            return why(
                "cancelled",
                format!(
                    "its calls were cancelled ({} times): the port was switched to non-blocking or disconnected",
                    st.cancelled
                ),
            );
        }
        if st.lost > 0 {
            return why(
                "lost",
                format!(
                    "{} messages to or from it were lost on the connection",
                    st.lost
                ),
            );
        }
        if server.state != crate::Lifecycle::Running {
            return why(
                "server-not-running",
                format!("`{}` is {}", server.name, server.state.name()),
            );
        }
        if is_push && port.subscribed.is_none() {
            return why(
                "not-subscribed",
                "connected, but the component never subscribed".to_owned(),
            );
        }
        if pattern == Pattern::Event && st.activations == 0 {
            return why(
                "event-not-activated",
                "the event was never activated, so the server tests nothing for it".to_owned(),
            );
        }
        if st.withheld > 0 {
            return why(
                "prescale",
                format!("the prescale held back all {} updates so far", st.withheld),
            );
        }
        let in_flight = self
            .trace
            .iter()
            .any(|r| r.port == name && r.status == Status::InFlight);
        if in_flight {
            return why(
                "in-flight",
                "a message is on its way: the connection's latency".to_owned(),
            );
        }
        let service = &server.services[wire.service.1];
        why(
            "nothing-sent",
            format!(
                "`{}.{}` has sent it nothing yet",
                server.name, service.spec.name
            ),
        )
    }
}
