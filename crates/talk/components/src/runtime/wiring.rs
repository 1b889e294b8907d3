//! The wiring pattern: a master (or the deployer) connects a client port to
//! a service and disconnects it, and a port can be switched to
//! non-blocking to cancel what waits on it.

use super::{Kind, Ref, Runtime, What, Wire};
use crate::link::Latency;
use crate::object::Object;
use crate::pattern::{Refusal, compatible};
use crate::trace::{Record, Status};

fn refusal(reason: &'static str, message: String) -> Refusal {
    Refusal { reason, message }
}

impl Runtime {
    /// `component.port` → its indices.
    pub(crate) fn port_ref(&self, name: &str) -> Result<Ref, Refusal> {
        let missing = || refusal("no-such-port", format!("there is no port `{name}`"));
        let (c, p) = name.split_once('.').ok_or_else(missing)?;
        let c = self.find(c).ok_or_else(missing)?;
        let p = self.slots[c]
            .ports
            .iter()
            .position(|s| s.spec.name == p)
            .ok_or_else(missing)?;
        Ok((c, p))
    }

    /// `component.service` → its indices.
    pub(crate) fn service_ref(&self, name: &str) -> Result<Ref, Refusal> {
        let missing = || refusal("no-such-service", format!("there is no service `{name}`"));
        let (c, s) = name.split_once('.').ok_or_else(missing)?;
        let c = self.find(c).ok_or_else(missing)?;
        let s = self.slots[c]
            .services
            .iter()
            .position(|x| x.spec.name == s)
            .ok_or_else(missing)?;
        Ok((c, s))
    }

    fn wiring_record(
        &mut self,
        kind: &'static str,
        by: &str,
        port: &str,
        service: &str,
        status: Status,
        summary: String,
    ) {
        let to = port.split('.').next().unwrap_or_default().to_owned();
        self.record(Record {
            seq: 0,
            pattern: "wiring",
            kind,
            from: by.to_owned(),
            to,
            port: port.to_owned(),
            service: service.to_owned(),
            sent: self.now,
            delivered: Some(self.now),
            status,
            summary,
        });
    }

    /// Wire `port` to `service`. `master`: the component asking, which must
    /// be a master and may wire only wireable ports; `None` is the
    /// deployer setting the system up, which may wire any port.
    pub fn connect(
        &mut self,
        port: &str,
        service: &str,
        by: &str,
        master: Option<usize>,
    ) -> Result<(), Refusal> {
        let result = self.check_connect(port, service, master);
        let (p, s) = match result {
            Ok(pair) => pair,
            Err(e) => {
                if let Ok((c, p)) = self.port_ref(port) {
                    self.slots[c].ports[p].refusal = Some(e.clone());
                }
                self.wiring_record(
                    "connect",
                    by,
                    port,
                    service,
                    Status::Refused,
                    e.message.clone(),
                );
                return Err(e);
            }
        };
        if self.slots[p.0].ports[p.1].wire.is_some() {
            self.disconnect(p, by);
        }
        let id = self.next_seq();
        let latency = self.latency;
        let slot = &mut self.slots[p.0].ports[p.1];
        slot.wire = Some(Wire {
            id,
            service: s,
            latency,
            last: [self.now; 2],
        });
        slot.refusal = None;
        let subscribed = slot.subscribed;
        self.wiring_record(
            "connect",
            by,
            port,
            service,
            Status::Done,
            format!("{port} → {service}"),
        );
        if let Some(prescale) = subscribed {
            let none = Object::new("Subscribe", serde_json::json!({ "prescale": prescale }));
            let _ = self.emit(p, Kind::Subscribe(prescale), none, None);
        }
        Ok(())
    }

    fn check_connect(
        &self,
        port: &str,
        service: &str,
        master: Option<usize>,
    ) -> Result<(Ref, Ref), Refusal> {
        let p = self.port_ref(port)?;
        let s = self.service_ref(service)?;
        let spec = &self.slots[p.0].ports[p.1].spec;
        if let Some(m) = master {
            if !self.slots[m].master {
                return Err(refusal(
                    "not-master",
                    format!("`{}` is not a wiring master", self.slots[m].name),
                ));
            }
            if !spec.wireable {
                return Err(refusal(
                    "not-wireable",
                    format!(
                        "port `{port}` is not wireable: only its own component's set-up connects it"
                    ),
                ));
            }
        }
        compatible(spec, &self.slots[s.0].services[s.1].spec)?;
        Ok((p, s))
    }

    /// Give the connection of `port` its own latency.
    pub fn set_latency(&mut self, port: &str, latency: Latency) -> Result<(), Refusal> {
        let (c, p) = self.port_ref(port)?;
        match self.slots[c].ports[p].wire.as_mut() {
            Some(w) => {
                w.latency = latency;
                Ok(())
            }
            None => Err(refusal(
                "not-connected",
                format!("port `{port}` is not connected"),
            )),
        }
    }

    /// Cut a port's connection: what is pending on it is cancelled, its
    /// subscription and events end at the service.
    pub(crate) fn disconnect(&mut self, (c, p): Ref, by: &str) {
        let Some(wire) = self.slots[c].ports[p].wire.take() else {
            return;
        };
        let service = &mut self.slots[wire.service.0].services[wire.service.1];
        service.subscribers.retain(|s| s.port != (c, p));
        service.activations.retain(|a| a.port != (c, p));
        service.pending.retain(|_, (port, _)| *port != (c, p));
        let waiting = self.slots[c].waiting;
        let port = &mut self.slots[c].ports[p];
        port.events.clear();
        for answer in port.answers.values_mut().filter(|a| a.is_none()) {
            *answer = Some(Err(Status::Disconnected));
            port.stats.cancelled += 1;
        }
        if let Some((wp, id)) = waiting
            && wp == p
        {
            self.push(self.now, What::Release(c, p, id, Status::Disconnected));
        }
        let (_, port_name, _, service_name) = self.names((c, p), Some(wire.service));
        self.wiring_record(
            "disconnect",
            by,
            &port_name,
            &service_name,
            Status::Done,
            format!("{port_name} cut"),
        );
    }

    pub(crate) fn disconnect_named(&mut self, port: &str, by: &str) {
        if let Ok(r) = self.port_ref(port) {
            self.disconnect(r, by);
        }
    }

    /// Non-blocking releases the call the activity waits in on this port
    /// with "cancelled", and later waits return at once.
    pub(crate) fn set_blocking(&mut self, (c, p): Ref, blocking: bool, by: &str) {
        self.slots[c].ports[p].blocking = blocking;
        if !blocking
            && let Some((wp, id)) = self.slots[c].waiting
            && wp == p
        {
            let port = &mut self.slots[c].ports[p];
            port.answers.remove(&id);
            port.stats.cancelled += 1;
            self.push(self.now, What::Release(c, p, id, Status::Cancelled));
        }
        let (_, port_name, ..) = self.names((c, p), None);
        let kind = if blocking { "block" } else { "cancel" };
        let summary = if blocking {
            "blocking again"
        } else {
            "non-blocking: waiting calls return cancelled"
        };
        self.wiring_record(kind, by, &port_name, "", Status::Done, summary.to_owned());
    }

    pub(crate) fn set_blocking_named(&mut self, port: &str, blocking: bool, by: &str) {
        if let Ok(r) = self.port_ref(port) {
            self.set_blocking(r, blocking, by);
        }
    }
}
