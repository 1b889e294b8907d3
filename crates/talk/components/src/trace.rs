//! The trace: every message the runtime carried, when it left, when (and
//! whether) it arrived, and a short summary of what it held.

use serde::Serialize;

/// What became of a message.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Status {
    /// Still on the wire.
    InFlight,
    Delivered,
    /// Dropped by the connection (its `loss`).
    Lost,
    /// Push: overwritten by a newer value before the subscriber read it.
    Skipped,
    /// A waiting call released by cancel, or an answer for a cancelled call.
    Cancelled,
    /// The port was disconnected (or rewired) while the message travelled.
    Disconnected,
    /// Sent from a port with no connection: it never left.
    NotConnected,
    /// The receiving component was not running.
    NotRunning,
    /// A wiring request that was refused.
    Refused,
    /// A wiring or state change that took effect.
    Done,
}

impl Status {
    pub fn name(self) -> &'static str {
        match self {
            Status::InFlight => "in-flight",
            Status::Delivered => "delivered",
            Status::Lost => "lost",
            Status::Skipped => "skipped",
            Status::Cancelled => "cancelled",
            Status::Disconnected => "disconnected",
            Status::NotConnected => "not-connected",
            Status::NotRunning => "not-running",
            Status::Refused => "refused",
            Status::Done => "done",
        }
    }
}

/// One line of the trace.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Record {
    pub seq: u64,
    /// `send`, `query`, `push-newest`, `push-timed`, `event`, `wiring`,
    /// `state` or `note`.
    pub pattern: &'static str,
    /// `command`, `request`, `answer`, `subscribe`, `unsubscribe`,
    /// `update`, `activate`, `deactivate`, `notify`, `connect`,
    /// `disconnect`, `cancel`, `state`, `note`.
    pub kind: &'static str,
    /// The components at either end, sender first.
    pub from: String,
    pub to: String,
    /// `component.port` and `component.service` (empty when not involved).
    pub port: String,
    pub service: String,
    pub sent: f64,
    /// Absent while in flight and for messages that never arrived.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub delivered: Option<f64>,
    pub status: Status,
    pub summary: String,
}
