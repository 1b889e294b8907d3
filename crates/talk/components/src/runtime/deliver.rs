//! Messages: putting them on a connection, and what happens when they
//! arrive at a service or back at a port.

use super::{Activation, Kind, Message, Ref, Runtime, Subscriber, What};
use crate::component::Lifecycle;
use crate::object::Object;
use crate::trace::{Record, Status};

impl Runtime {
    /// The `component.port` and `component.service` names of a pair.
    pub(crate) fn names(
        &self,
        port: Ref,
        service: Option<Ref>,
    ) -> (String, String, String, String) {
        let client = &self.slots[port.0];
        let port_name = format!("{}.{}", client.name, client.ports[port.1].spec.name);
        let (server, service_name) = match service {
            Some((c, s)) => {
                let slot = &self.slots[c];
                (
                    slot.name.clone(),
                    format!("{}.{}", slot.name, slot.services[s].spec.name),
                )
            }
            None => (String::new(), String::new()),
        };
        (client.name.clone(), port_name, server, service_name)
    }

    /// Put a message on port `port`'s connection (either way). `expect`:
    /// for messages from the server, the connection they belong to; if
    /// the port has been rewired since, nothing is sent.
    pub(crate) fn emit(
        &mut self,
        port: Ref,
        kind: Kind,
        object: Object,
        expect: Option<u64>,
    ) -> Result<(), Status> {
        let up = kind.upstream();
        let pattern = self.slots[port.0].ports[port.1].spec.pattern.name();
        let wire = self.slots[port.0].ports[port.1].wire.clone();
        let wire = match wire {
            Some(w) if expect.is_none_or(|e| e == w.id) => w,
            _ => {
                if up {
                    let (client, port_name, ..) = self.names(port, None);
                    self.slots[port.0].ports[port.1].stats.not_connected += 1;
                    self.record(Record {
                        seq: 0,
                        pattern,
                        kind: kind.name(),
                        from: client,
                        to: String::new(),
                        port: port_name,
                        service: String::new(),
                        sent: self.now,
                        delivered: None,
                        status: Status::NotConnected,
                        summary: object.summary(),
                    });
                }
                return Err(Status::NotConnected);
            }
        };
        // Jitter and loss are drawn by the message's own number, so a change
        // scheduled for later (a script item) cannot alter what came before.
        self.messages += 1;
        let seq = self.messages;
        let direction = usize::from(!up);
        let arrival = wire
            .latency
            .arrival(self.seed, seq, self.now, wire.last[direction]);
        let (client, port_name, server, service_name) = self.names(port, Some(wire.service));
        let (from, to) = if up {
            (client, server)
        } else {
            (server, client)
        };
        let record = self.record(Record {
            seq: 0,
            pattern,
            kind: kind.name(),
            from,
            to,
            port: port_name,
            service: service_name,
            sent: self.now,
            delivered: None,
            status: if arrival.is_some() {
                Status::InFlight
            } else {
                Status::Lost
            },
            summary: object.summary(),
        });
        let stats = &mut self.slots[port.0].ports[port.1].stats;
        if up {
            stats.sent += 1;
        }
        let Some(at) = arrival else {
            stats.lost += 1;
            return Ok(());
        };
        if let Some(w) = self.slots[port.0].ports[port.1].wire.as_mut() {
            w.last[direction] = at;
        }
        self.push(
            at,
            What::Deliver(Box::new(Message {
                record,
                wire: wire.id,
                port,
                service: wire.service,
                kind,
                object,
            })),
        );
        Ok(())
    }

    pub(crate) fn deliver(&mut self, m: Message) {
        let current = self.slots[m.port.0].ports[m.port.1]
            .wire
            .as_ref()
            .map(|w| w.id);
        if current != Some(m.wire) {
            self.slots[m.port.0].ports[m.port.1].stats.disconnected += 1;
            self.set_status(m.record, Status::Disconnected);
            return;
        }
        let receiver = if m.kind.upstream() {
            m.service.0
        } else {
            m.port.0
        };
        if self.slots[receiver].state != Lifecycle::Running {
            self.set_status(m.record, Status::NotRunning);
            if let Kind::Request(id) = m.kind {
                let none = Object::new("None", serde_json::Value::Null);
                let _ = self.emit(
                    m.port,
                    Kind::Answer(id, Some(Status::NotRunning)),
                    none,
                    Some(m.wire),
                );
            }
            return;
        }
        if let Some(r) = m.record.and_then(|i| self.trace.get_mut(i)) {
            r.delivered = Some(self.now);
            r.status = Status::Delivered;
        }
        if m.kind.upstream() {
            self.at_service(m);
        } else {
            self.at_port(m);
        }
    }

    fn at_service(&mut self, m: Message) {
        let (c, s) = m.service;
        let name = self.slots[c].services[s].spec.name.clone();
        match m.kind {
            Kind::Command => self.call(c, |comp, cx| comp.command(&name, &m.object, cx)),
            Kind::Request(id) => {
                self.slots[c].services[s]
                    .pending
                    .insert(id, (m.port, m.wire));
                let ticket = super::Ticket { service: s, id };
                self.call(c, |comp, cx| comp.request(&name, ticket, &m.object, cx));
            }
            Kind::Subscribe(prescale) => {
                let service = &mut self.slots[c].services[s];
                service.subscribers.retain(|sub| sub.port != m.port);
                service.subscribers.push(Subscriber {
                    port: m.port,
                    wire: m.wire,
                    prescale: prescale.max(1),
                    ticks: 0,
                });
                // A late subscriber to push newest gets the current value.
                let newest = service.spec.pattern == crate::Pattern::PushNewest;
                if let (true, Some(value)) = (newest, service.current.clone()) {
                    let _ = self.emit(m.port, Kind::Update, value, Some(m.wire));
                }
            }
            Kind::Unsubscribe => {
                self.slots[c].services[s]
                    .subscribers
                    .retain(|sub| sub.port != m.port);
            }
            Kind::Activate(id, mode) => {
                self.slots[c].services[s].activations.push(Activation {
                    id,
                    port: m.port,
                    wire: m.wire,
                    params: m.object.clone(),
                    mode,
                    was_true: false,
                });
                self.call(c, |comp, cx| comp.activated(&name, cx));
            }
            Kind::Deactivate(id) => {
                self.slots[c].services[s].activations.retain(|a| a.id != id);
            }
            Kind::Answer(..) | Kind::Update | Kind::Notify(_) => {}
        }
    }

    fn at_port(&mut self, m: Message) {
        let (c, p) = m.port;
        let name = self.slots[c].ports[p].spec.name.clone();
        match m.kind {
            Kind::Answer(id, why) => {
                let port = &mut self.slots[c].ports[p];
                let Some(slot) = port.answers.get_mut(&id) else {
                    // Nobody waits for it any more (cancelled or forgotten).
                    self.set_status(m.record, Status::Cancelled);
                    return;
                };
                port.stats.received += 1;
                let result = match why {
                    Some(status) => Err(status),
                    None => Ok(m.object),
                };
                *slot = Some(result.clone());
                if self.slots[c].waiting == Some((p, id)) {
                    self.slots[c].waiting = None;
                    self.slots[c].ports[p].answers.remove(&id);
                    self.call(c, |comp, cx| comp.answered(&name, id, result, cx));
                    self.resume(c);
                }
            }
            Kind::Update => {
                let port = &mut self.slots[c].ports[p];
                port.stats.received += 1;
                let overwritten = port.unread.replace(m.record.unwrap_or(usize::MAX));
                port.newest = Some(m.object);
                if let Some(old) = overwritten {
                    port.stats.skipped += 1;
                    self.set_status(Some(old), Status::Skipped);
                }
                self.schedule_wake(c);
            }
            Kind::Notify(id) => {
                let port = &mut self.slots[c].ports[p];
                let Some(k) = port.events.iter().position(|(e, _)| *e == id) else {
                    self.set_status(m.record, Status::Cancelled);
                    return;
                };
                port.stats.received += 1;
                if port.events[k].1 == super::Mode::Once {
                    port.events.remove(k);
                }
                self.call(c, |comp, cx| comp.notified(&name, id, &m.object, cx));
            }
            _ => {}
        }
    }

    /// A push-timed service's period is up: every subscriber gets the
    /// current value, or every n-th time with prescale n.
    pub(crate) fn tick(&mut self, c: usize, s: usize) {
        let running = self.slots[c].state == Lifecycle::Running;
        let service = &mut self.slots[c].services[s];
        if !service.running || !running {
            service.running = false;
            return;
        }
        let period = service.period;
        let value = service.current.clone();
        let mut due = Vec::new();
        for sub in &mut service.subscribers {
            sub.ticks += 1;
            let send = (sub.ticks - 1) % u64::from(sub.prescale) == 0;
            due.push((sub.port, sub.wire, send));
        }
        for (port, wire, send) in due {
            match (send, value.clone()) {
                (true, Some(v)) => {
                    let _ = self.emit(port, Kind::Update, v, Some(wire));
                }
                (false, _) => self.slots[port.0].ports[port.1].stats.withheld += 1,
                (true, None) => {}
            }
        }
        self.push(self.now + period, What::Tick(c, s));
    }
}
