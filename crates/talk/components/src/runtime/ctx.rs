//! What a component may do, through the patterns only: the handle the
//! runtime passes to every handler.

use kinolab_world::Sim;

use super::{Kind, Mode, Runtime, Ticket, What};
use crate::object::Object;
use crate::pattern::{Pattern, Refusal};
use crate::trace::{Record, Status};

/// A component's view of the runtime during one handler.
#[derive(Debug)]
pub struct Ctx<'a> {
    rt: &'a mut Runtime,
    me: usize,
}

impl<'a> Ctx<'a> {
    pub(crate) fn new(rt: &'a mut Runtime, me: usize) -> Self {
        Self { rt, me }
    }

    pub fn now(&self) -> f64 {
        self.rt.now
    }

    pub fn name(&self) -> &str {
        &self.rt.slots[self.me].name
    }

    /// Call [`crate::Component::timer`] with `tag` after `delay` seconds.
    pub fn after(&mut self, delay: f64, tag: u32) {
        let delay = if delay.is_finite() {
            delay.max(super::MIN_DELAY)
        } else {
            super::MIN_DELAY
        };
        self.rt.push(self.rt.now + delay, What::Timer(self.me, tag));
    }

    /// The activity works for `seconds`: timers and updates wait.
    pub fn busy(&mut self, seconds: f64) {
        let slot = &mut self.rt.slots[self.me];
        slot.busy_until = slot
            .busy_until
            .max(self.rt.now + seconds.clamp(0.0, 3600.0));
    }

    fn port(&self, name: &str, pattern: Pattern) -> Result<usize, Status> {
        self.rt.slots[self.me]
            .ports
            .iter()
            .position(|p| p.spec.name == name && p.spec.pattern == pattern)
            .ok_or(Status::NotConnected)
    }

    fn service(&self, name: &str, pattern: Pattern) -> Option<usize> {
        self.rt.slots[self.me]
            .services
            .iter()
            .position(|s| s.spec.name == name && s.spec.pattern == pattern)
    }

    /// Send: one-way, no answer.
    pub fn send(&mut self, port: &str, object: Object) -> Result<(), Status> {
        let p = self.port(port, Pattern::Send)?;
        self.rt.emit((self.me, p), Kind::Command, object, None)
    }

    /// Query, asynchronous use: the request leaves and its id comes back at
    /// once; collect the answer with [`Ctx::receive`] or [`Ctx::wait`].
    pub fn request(&mut self, port: &str, object: Object) -> Result<u64, Status> {
        let p = self.port(port, Pattern::Query)?;
        let id = self.rt.next_seq();
        self.rt
            .emit((self.me, p), Kind::Request(id), object, None)?;
        self.rt.slots[self.me].ports[p].answers.insert(id, None);
        Ok(id)
    }

    /// Query, synchronous use: request and wait. The activity is blocked
    /// until [`crate::Component::answered`] brings the answer (or why not).
    /// A non-blocking port returns "cancelled" at once without sending.
    pub fn query(&mut self, port: &str, object: Object) -> Result<u64, Status> {
        let p = self.port(port, Pattern::Query)?;
        if !self.rt.slots[self.me].ports[p].blocking {
            self.rt.slots[self.me].ports[p].stats.cancelled += 1;
            return Err(Status::Cancelled);
        }
        let id = self.request(port, object)?;
        self.rt.slots[self.me].waiting = Some((p, id));
        Ok(id)
    }

    /// Whether the answer to `id` has come; takes it if so.
    pub fn receive(&mut self, port: &str, id: u64) -> Option<Result<Object, Status>> {
        let p = self.port(port, Pattern::Query).ok()?;
        let answers = &mut self.rt.slots[self.me].ports[p].answers;
        if answers.get(&id)?.is_some() {
            answers.remove(&id).flatten()
        } else {
            None
        }
    }

    /// Wait for the answer to `id`: returns it now if it is here (or the
    /// port is non-blocking: "cancelled"), else blocks the activity until
    /// [`crate::Component::answered`].
    pub fn wait(&mut self, port: &str, id: u64) -> Option<Result<Object, Status>> {
        let Ok(p) = self.port(port, Pattern::Query) else {
            return Some(Err(Status::NotConnected));
        };
        if let Some(answer) = self.receive(port, id) {
            return Some(answer);
        }
        let slot = &mut self.rt.slots[self.me];
        if !slot.ports[p].answers.contains_key(&id) {
            return Some(Err(Status::Cancelled));
        }
        if !slot.ports[p].blocking {
            slot.ports[p].stats.cancelled += 1;
            return Some(Err(Status::Cancelled));
        }
        slot.waiting = Some((p, id));
        None
    }

    /// Answer a query (now, or later from a timer).
    pub fn answer(&mut self, ticket: Ticket, object: Object) {
        let Some(&(port, wire)) = self.rt.slots[self.me].services[ticket.service]
            .pending
            .get(&ticket.id)
        else {
            return;
        };
        self.rt.slots[self.me].services[ticket.service]
            .pending
            .remove(&ticket.id);
        let _ = self
            .rt
            .emit(port, Kind::Answer(ticket.id, None), object, Some(wire));
    }

    /// Set a push service's current value. Push newest sends it to every
    /// subscriber now; push timed sends it at its next period.
    pub fn publish(&mut self, service: &str, object: Object) {
        let s = self
            .service(service, Pattern::PushNewest)
            .or_else(|| self.service(service, Pattern::PushTimed));
        let Some(s) = s else { return };
        let slot = &mut self.rt.slots[self.me].services[s];
        slot.current = Some(object.clone());
        if slot.spec.pattern == Pattern::PushNewest {
            let subs: Vec<_> = slot.subscribers.iter().map(|x| (x.port, x.wire)).collect();
            for (port, wire) in subs {
                let _ = self.rt.emit(port, Kind::Update, object.clone(), Some(wire));
            }
        }
    }

    /// Start a push-timed service's clock with `period` seconds.
    pub fn start_timed(&mut self, service: &str, period: f64) {
        let Some(s) = self.service(service, Pattern::PushTimed) else {
            return;
        };
        let slot = &mut self.rt.slots[self.me].services[s];
        slot.period = period.clamp(super::MIN_DELAY * 10.0, 3600.0);
        if !slot.running {
            slot.running = true;
            let at = self.rt.now + slot.period;
            self.rt.push(at, What::Tick(self.me, s));
        }
    }

    pub fn stop_timed(&mut self, service: &str) {
        if let Some(s) = self.service(service, Pattern::PushTimed) {
            self.rt.slots[self.me].services[s].running = false;
        }
    }

    /// Subscribe a push port (every `prescale`-th update, for push timed).
    /// The wish outlives rewiring: a new connection subscribes again.
    pub fn subscribe(&mut self, port: &str, prescale: u32) {
        let p = self
            .port(port, Pattern::PushNewest)
            .or_else(|_| self.port(port, Pattern::PushTimed));
        let Ok(p) = p else { return };
        let prescale = prescale.max(1);
        self.rt.slots[self.me].ports[p].subscribed = Some(prescale);
        let request = Object::new("Subscribe", serde_json::json!({ "prescale": prescale }));
        let _ = self
            .rt
            .emit((self.me, p), Kind::Subscribe(prescale), request, None);
    }

    pub fn unsubscribe(&mut self, port: &str) {
        let p = self
            .port(port, Pattern::PushNewest)
            .or_else(|_| self.port(port, Pattern::PushTimed));
        let Ok(p) = p else { return };
        self.rt.slots[self.me].ports[p].subscribed = None;
        let request = Object::new("Unsubscribe", serde_json::Value::Null);
        let _ = self.rt.emit((self.me, p), Kind::Unsubscribe, request, None);
    }

    /// The newest value a push port holds (get update, non-blocking).
    pub fn newest(&self, port: &str) -> Option<&Object> {
        let slot = &self.rt.slots[self.me];
        slot.ports
            .iter()
            .find(|p| p.spec.name == port)?
            .newest
            .as_ref()
    }

    /// Activate an event with parameters; its id comes back.
    pub fn activate(&mut self, port: &str, params: Object, mode: Mode) -> Result<u64, Status> {
        let p = self.port(port, Pattern::Event)?;
        let id = self.rt.next_seq();
        self.rt
            .emit((self.me, p), Kind::Activate(id, mode), params, None)?;
        let port = &mut self.rt.slots[self.me].ports[p];
        port.events.push((id, mode));
        port.stats.activations += 1;
        Ok(id)
    }

    pub fn deactivate(&mut self, port: &str, id: u64) {
        let Ok(p) = self.port(port, Pattern::Event) else {
            return;
        };
        self.rt.slots[self.me].ports[p]
            .events
            .retain(|(e, _)| *e != id);
        let none = Object::new("Deactivate", serde_json::Value::Null);
        let _ = self.rt.emit((self.me, p), Kind::Deactivate(id), none, None);
    }

    /// Test every activation of event `service` with `condition` on this
    /// component's own data; notify those that just became true (a
    /// once-event then ends).
    pub fn test_events(&mut self, service: &str, condition: &dyn Fn(&Object) -> Option<Object>) {
        let Some(s) = self.service(service, Pattern::Event) else {
            return;
        };
        let mut fire = Vec::new();
        let slot = &mut self.rt.slots[self.me].services[s];
        slot.activations.retain_mut(|a| {
            let hit = condition(&a.params);
            let rising = hit.is_some() && !a.was_true;
            a.was_true = hit.is_some();
            if let (true, Some(h)) = (rising, hit) {
                fire.push((a.port, a.wire, a.id, h));
                return a.mode == Mode::Continuous;
            }
            true
        });
        for (port, wire, id, object) in fire {
            let _ = self.rt.emit(port, Kind::Notify(id), object, Some(wire));
        }
    }

    /// Wiring (this component must be a master): connect a wireable port
    /// `component.port` to `component.service`.
    pub fn connect(&mut self, port: &str, service: &str) -> Result<(), Refusal> {
        let by = self.rt.slots[self.me].name.clone();
        self.rt.connect(port, service, &by, Some(self.me))
    }

    /// Wiring: cut `component.port` (a master only, wireable ports only).
    pub fn disconnect(&mut self, port: &str) -> Result<(), Refusal> {
        let by = self.rt.slots[self.me].name.clone();
        if !self.rt.slots[self.me].master {
            return Err(Refusal {
                reason: "not-master",
                message: format!("`{by}` is not a wiring master"),
            });
        }
        let r = self.rt.port_ref(port)?;
        self.rt.disconnect(r, &by);
        Ok(())
    }

    /// Switch one of this component's ports to non-blocking (cancel) or back.
    pub fn set_blocking(&mut self, port: &str, blocking: bool) {
        let me = self.me;
        if let Some(p) = self.rt.slots[me]
            .ports
            .iter()
            .position(|x| x.spec.name == port)
        {
            let by = self.rt.slots[me].name.clone();
            self.rt.set_blocking((me, p), blocking, &by);
        }
    }

    /// A line in the trace from this component (what it decided, and why).
    pub fn note(&mut self, text: &str) {
        let name = self.rt.slots[self.me].name.clone();
        self.rt.record(Record {
            seq: 0,
            pattern: "note",
            kind: "note",
            from: name.clone(),
            to: name,
            port: String::new(),
            service: String::new(),
            sent: self.rt.now,
            delivered: Some(self.rt.now),
            status: Status::Done,
            summary: text.to_owned(),
        });
    }

    /// The simulated world (for the robot's sensors and its base only:
    /// physics, not communication).
    pub fn world(&mut self) -> Option<&mut Sim> {
        self.rt.world.as_mut()
    }
}
