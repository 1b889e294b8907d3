//! The six communication patterns, the services components provide and the
//! client ports they use, and the rule that decides whether a port may be
//! wired to a service.

use std::fmt;

use serde::{Deserialize, Serialize};

/// How two halves talk. Wiring, the sixth pattern, is not a port kind: it
/// is what a master does to other components' ports (see
/// [`crate::runtime::Ctx::connect`]), so no port can be wired to it.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum Pattern {
    /// One-way, client → server: commands that need no answer.
    Send,
    /// Request → answer, started by the client.
    Query,
    /// 1 → n whenever the server has a new value; subscribers see the newest.
    PushNewest,
    /// 1 → n every period; a subscriber may ask for every n-th.
    PushTimed,
    /// The client activates a condition; the server tests it on its own data
    /// and notifies when it becomes true (once or every time).
    Event,
}

impl Pattern {
    pub const ALL: [Pattern; 5] = [
        Pattern::Send,
        Pattern::Query,
        Pattern::PushNewest,
        Pattern::PushTimed,
        Pattern::Event,
    ];

    /// Every pattern's name, in [`Pattern::ALL`]'s order.
    pub const NAMES: [&'static str; 5] = {
        let mut names = [""; 5];
        let mut i = 0;
        while i < 5 {
            names[i] = Self::ALL[i].name();
            i += 1;
        }
        names
    };

    pub const fn name(self) -> &'static str {
        match self {
            Pattern::Send => "send",
            Pattern::Query => "query",
            Pattern::PushNewest => "push-newest",
            Pattern::PushTimed => "push-timed",
            Pattern::Event => "event",
        }
    }

    /// The relation between the two halves.
    pub fn relation(self) -> &'static str {
        match self {
            Pattern::PushNewest | Pattern::PushTimed => "publisher/subscriber",
            _ => "client/server",
        }
    }

    pub fn from_name(name: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|p| p.name() == name)
    }
}

impl fmt::Display for Pattern {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// The communication object types of a service or port: what the client
/// sends (or receives, for the push patterns) and, for a query or an
/// event, what comes back.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
pub struct Signature {
    pub object: String,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub answer: Option<String>,
}

impl Signature {
    pub fn one(object: &str) -> Self {
        Self {
            object: object.to_owned(),
            answer: None,
        }
    }

    pub fn two(object: &str, answer: &str) -> Self {
        Self {
            object: object.to_owned(),
            answer: Some(answer.to_owned()),
        }
    }
}

impl fmt::Display for Signature {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match &self.answer {
            Some(a) => write!(f, "{} → {a}", self.object),
            None => f.write_str(&self.object),
        }
    }
}

/// A service a component provides: a pattern with its object types.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ServiceSpec {
    pub name: String,
    pub pattern: Pattern,
    pub signature: Signature,
}

/// A client port a component uses. Only a wireable port may be connected
/// by a master while the system runs.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct PortSpec {
    pub name: String,
    pub pattern: Pattern,
    pub signature: Signature,
    pub wireable: bool,
}

impl ServiceSpec {
    pub fn new(name: &str, pattern: Pattern, signature: Signature) -> Self {
        Self {
            name: name.to_owned(),
            pattern,
            signature,
        }
    }
}

impl PortSpec {
    pub fn new(name: &str, pattern: Pattern, signature: Signature, wireable: bool) -> Self {
        Self {
            name: name.to_owned(),
            pattern,
            signature,
            wireable,
        }
    }
}

/// Why a connection was refused.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Refusal {
    /// `no-such-port`, `no-such-service`, `not-wireable`, `pattern`,
    /// `types`, `not-master`.
    pub reason: &'static str,
    pub message: String,
}

impl fmt::Display for Refusal {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.message)
    }
}

/// Whether `port` may talk to `service`: the pattern *and* the object
/// types must both match. A matching type over the wrong pattern is
/// refused too (a scan stream is not a scan query).
pub fn compatible(port: &PortSpec, service: &ServiceSpec) -> Result<(), Refusal> {
    if port.pattern != service.pattern {
        return Err(Refusal {
            reason: "pattern",
            message: format!(
                "port `{}` speaks {} but service `{}` speaks {}",
                port.name, port.pattern, service.name, service.pattern
            ),
        });
    }
    if port.signature != service.signature {
        return Err(Refusal {
            reason: "types",
            message: format!(
                "both speak {}, but port `{}` carries {} and service `{}` carries {}",
                port.pattern, port.name, port.signature, service.name, service.signature
            ),
        });
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn wiring_needs_pattern_and_types_to_match() {
        let scans = ServiceSpec::new("scan", Pattern::PushNewest, Signature::one("Scan"));
        let port = |p, t: &str| PortSpec::new("in", p, Signature::one(t), true);
        assert!(compatible(&port(Pattern::PushNewest, "Scan"), &scans).is_ok());
        let e = compatible(&port(Pattern::PushTimed, "Scan"), &scans).unwrap_err();
        assert_eq!(e.reason, "pattern");
        assert!(e.message.contains("push-timed") && e.message.contains("push-newest"));
        let e = compatible(&port(Pattern::PushNewest, "Pose"), &scans).unwrap_err();
        assert_eq!(e.reason, "types");
        // A query whose answer type differs is refused too.
        let path = ServiceSpec::new("path", Pattern::Query, Signature::two("Goal", "Path"));
        let asks = PortSpec::new("ask", Pattern::Query, Signature::two("Goal", "Map"), true);
        assert_eq!(compatible(&asks, &path).unwrap_err().reason, "types");
        for p in Pattern::ALL {
            assert_eq!(Pattern::from_name(p.name()), Some(p));
        }
    }
}
