//! A snapshot of the running system for people: each component with its
//! state, services and ports, where each port is wired and what it saw.

use serde::Serialize;

use crate::component::Lifecycle;
use crate::pattern::{Pattern, Signature};
use crate::runtime::{PortStats, Runtime};

#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ServiceView {
    pub name: String,
    pub pattern: Pattern,
    pub signature: Signature,
    pub subscribers: usize,
    pub activations: usize,
    pub pending: usize,
}

#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct PortView {
    pub name: String,
    pub pattern: Pattern,
    pub signature: Signature,
    pub wireable: bool,
    pub blocking: bool,
    /// `component.service`, when connected.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub connected_to: Option<String>,
    pub stats: PortStats,
    /// The last refused connection's reason, until a connection succeeds.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub refused: Option<String>,
}

#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ComponentView {
    pub name: String,
    pub state: Lifecycle,
    pub master: bool,
    /// Blocked in a call on this port.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub waiting_on: Option<String>,
    pub status: String,
    pub services: Vec<ServiceView>,
    pub ports: Vec<PortView>,
}

impl Runtime {
    /// Every component as it stands now.
    pub fn view(&self) -> Vec<ComponentView> {
        self.slots
            .iter()
            .map(|slot| ComponentView {
                name: slot.name.clone(),
                state: slot.state,
                master: slot.master,
                waiting_on: slot.waiting.map(|(p, _)| slot.ports[p].spec.name.clone()),
                status: slot
                    .component
                    .as_ref()
                    .map(|c| c.status())
                    .unwrap_or_default(),
                services: slot
                    .services
                    .iter()
                    .map(|s| ServiceView {
                        name: s.spec.name.clone(),
                        pattern: s.spec.pattern,
                        signature: s.spec.signature.clone(),
                        subscribers: s.subscribers.len(),
                        activations: s.activations.len(),
                        pending: s.pending.len(),
                    })
                    .collect(),
                ports: slot
                    .ports
                    .iter()
                    .map(|p| PortView {
                        name: p.spec.name.clone(),
                        pattern: p.spec.pattern,
                        signature: p.spec.signature.clone(),
                        wireable: p.spec.wireable,
                        blocking: p.blocking,
                        connected_to: p.wire.as_ref().map(|w| {
                            let s = &self.slots[w.service.0];
                            format!("{}.{}", s.name, s.services[w.service.1].spec.name)
                        }),
                        stats: p.stats,
                        refused: p.refusal.as_ref().map(|r| r.message.clone()),
                    })
                    .collect(),
            })
            .collect()
    }

    /// The component called `name`, as it stands now.
    pub fn component(&self, name: &str) -> Option<ComponentView> {
        self.view().into_iter().find(|c| c.name == name)
    }

    /// The lifecycle state of `name`.
    pub fn state(&self, name: &str) -> Option<Lifecycle> {
        self.find(name).map(|c| self.slots[c].state)
    }
}
