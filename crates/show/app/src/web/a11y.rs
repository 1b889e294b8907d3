//! The lab for a screen reader. egui describes every widget to AccessKit
//! each frame (role, name, value, state, place), but eframe's web backend
//! drops that description, so to assistive technology the canvas is empty.
//! Once support is turned on (the page's first, visually hidden button, or
//! `?a11y` in the address), this mirror keeps invisible elements over the
//! canvas that carry the same roles, names, values, states and positions,
//! in reading order, and turns what a screen reader does to them (click,
//! focus, step a slider) into egui's own action requests.
//!
//! Off by default: describing every widget costs time each frame, and only
//! a learner who needs it should pay for it.

use std::cell::RefCell;
use std::collections::{HashMap, HashSet};

use egui::accesskit::{
    Action, ActionData, ActionRequest, Node, NodeId, Role, Toggled, TreeId, TreeUpdate,
};
use wasm_bindgen::JsCast as _;
use wasm_bindgen::closure::Closure;

/// The page's container for the mirrored elements.
const CONTAINER: &str = "kinolab-a11y";
/// The button that turns support on.
const SWITCH: &str = "kinolab-a11y-on";
/// The attribute holding a mirrored element's node id.
const NODE: &str = "data-node";

thread_local! {
    static MIRROR: RefCell<Mirror> = RefCell::new(Mirror::default());
}

#[derive(Default)]
struct Mirror {
    /// Support asked for; `on` once egui has been told.
    wanted: bool,
    on: bool,
    /// Each mirrored node's element and the node as last written.
    elements: HashMap<NodeId, (web_sys::Element, Node)>,
    /// Requests from the page, for egui's next frame.
    actions: Vec<ActionRequest>,
}

/// Hooks the mirror into egui's frames and the page's switch.
pub fn install(ctx: &egui::Context) {
    ctx.add_plugin(Plugin);
    let wanted = super::window()
        .and_then(|w| w.location().search().ok())
        .is_some_and(|q| q.contains("a11y"));
    MIRROR.with_borrow_mut(|m| m.wanted = wanted);
    let Some(document) = super::window().and_then(|w| w.document()) else {
        return;
    };
    if let Some(switch) = document.get_element_by_id(SWITCH) {
        let ctx = ctx.clone();
        let on = Closure::<dyn FnMut(web_sys::Event)>::new(move |_| {
            MIRROR.with_borrow_mut(|m| m.wanted = true);
            ctx.request_repaint();
        });
        let _ = switch.add_event_listener_with_callback("click", on.as_ref().unchecked_ref());
        on.forget();
    }
    if let Some(container) = document.get_element_by_id(CONTAINER) {
        for kind in ["click", "focusin", "keydown", "input"] {
            let ctx = ctx.clone();
            let act = Closure::<dyn FnMut(web_sys::Event)>::new(move |e: web_sys::Event| {
                if let Some(request) = request_for(&e) {
                    MIRROR.with_borrow_mut(|m| m.actions.push(request));
                    ctx.request_repaint();
                }
            });
            let _ = container.add_event_listener_with_callback(kind, act.as_ref().unchecked_ref());
            act.forget();
        }
    }
}

/// The egui action a page event on a mirrored element asks for. A text
/// field's every edit hands egui its whole new text; the arrow keys in it
/// move the caret, as they do in any text field.
fn request_for(e: &web_sys::Event) -> Option<ActionRequest> {
    let target = e.target()?.dyn_into::<web_sys::Element>().ok()?;
    let node = target.get_attribute(NODE)?.parse().ok()?;
    let mut data = None;
    let action = match e.type_().as_str() {
        "click" => Action::Click,
        "focusin" => Action::Focus,
        "input" => {
            data = Some(ActionData::Value(text_of(&target)?.into()));
            Action::SetValue
        }
        "keydown" if text_of(&target).is_some() => return None,
        "keydown" => {
            let key = e.dyn_ref::<web_sys::KeyboardEvent>()?.key();
            match key.as_str() {
                "ArrowUp" | "ArrowRight" => Action::Increment,
                "ArrowDown" | "ArrowLeft" => Action::Decrement,
                _ => return None,
            }
        }
        _ => return None,
    };
    Some(ActionRequest {
        action,
        target_tree: TreeId::ROOT,
        target_node: NodeId(node),
        data,
    })
}

/// The text in a mirrored text field; `None` for any other element.
fn text_of(element: &web_sys::Element) -> Option<String> {
    if let Some(input) = element.dyn_ref::<web_sys::HtmlInputElement>() {
        return Some(input.value());
    }
    element
        .dyn_ref::<web_sys::HtmlTextAreaElement>()
        .map(web_sys::HtmlTextAreaElement::value)
}

/// Show egui's text in a mirrored text field, unless the learner is typing
/// in it (their caret stays where it is).
fn set_text(element: &web_sys::Element, text: &str) {
    let typing = super::window()
        .and_then(|w| w.document())
        .and_then(|d| d.active_element())
        .is_some_and(|a| &a == element);
    if typing || text_of(element).as_deref() == Some(text) {
        return;
    }
    if let Some(input) = element.dyn_ref::<web_sys::HtmlInputElement>() {
        input.set_value(text);
    } else if let Some(area) = element.dyn_ref::<web_sys::HtmlTextAreaElement>() {
        area.set_value(text);
    }
}

struct Plugin;

impl egui::Plugin for Plugin {
    fn debug_name(&self) -> &'static str {
        "kinolab screen-reader mirror"
    }

    fn input_hook(&mut self, ctx: &egui::Context, input: &mut egui::RawInput) {
        MIRROR.with_borrow_mut(|m| {
            if m.wanted && !m.on {
                m.on = true;
                ctx.enable_accesskit();
                switched_on();
            }
            let requests = m.actions.drain(..);
            input
                .events
                .extend(requests.map(egui::Event::AccessKitActionRequest));
        });
    }

    fn output_hook(&mut self, ctx: &egui::Context, output: &mut egui::FullOutput) {
        if let Some(update) = output.platform_output.accesskit_update.take() {
            // egui's bounds are in points; a point is `zoom` CSS pixels.
            let zoom = f64::from(ctx.zoom_factor());
            MIRROR.with_borrow_mut(|m| m.apply(update, zoom));
        }
    }
}

/// The switch says support is on.
fn switched_on() {
    let switch = super::window()
        .and_then(|w| w.document())
        .and_then(|d| d.get_element_by_id(SWITCH));
    if let Some(switch) = switch {
        switch.set_text_content(Some("Screen reader support is on"));
        let _ = switch.set_attribute("aria-pressed", "true");
    }
}

impl Mirror {
    /// Bring the page's elements in line with egui's whole tree.
    fn apply(&mut self, update: TreeUpdate, zoom: f64) {
        let Some(document) = super::window().and_then(|w| w.document()) else {
            return;
        };
        let Some(container) = document.get_element_by_id(CONTAINER) else {
            return;
        };
        // The row-by-row text runs inside a label repeat its text: the
        // label's element already holds it.
        let nodes: Vec<(NodeId, Node)> = update
            .nodes
            .into_iter()
            .filter(|(_, n)| n.role() != Role::TextRun)
            .collect();
        let present: HashSet<NodeId> = nodes.iter().map(|(id, _)| *id).collect();
        let parent_of: HashMap<NodeId, NodeId> = nodes
            .iter()
            .flat_map(|(id, n)| n.children().iter().map(move |c| (*c, *id)))
            .collect();
        self.elements.retain(|id, (element, _)| {
            let keep = present.contains(id);
            if !keep {
                element.remove();
            }
            keep
        });
        let mut reorder = Vec::new();
        for (id, node) in nodes {
            if let Some((_, old)) = self.elements.get(&id)
                && *old == node
            {
                continue;
            }
            let Some((element, fresh)) = self.element(&document, id, node.role()) else {
                continue;
            };
            describe(&element, id, &node, zoom);
            reorder.push(id);
            // A new element goes where its parent keeps its children.
            if fresh && let Some(parent) = parent_of.get(&id) {
                reorder.push(*parent);
            }
            self.elements.insert(id, (element, node));
        }
        // Children in reading order, under their parent.
        for id in reorder {
            let Some((parent, node)) = self.elements.get(&id) else {
                continue;
            };
            for child in node.children() {
                if let Some((element, _)) = self.elements.get(child) {
                    let _ = parent.append_child(element);
                }
            }
        }
        let root = update.tree.map(|t| t.root);
        if let Some((element, _)) = root.and_then(|r| self.elements.get(&r))
            && element.parent_element().is_none()
        {
            let _ = container.append_child(element);
        }
        if let Some((element, _)) = self.elements.get(&update.focus)
            && let Some(html) = element.dyn_ref::<web_sys::HtmlElement>()
            && Some(update.focus) != root
        {
            let active = document.active_element();
            if active.as_ref() != Some(element)
                && active
                    .is_some_and(|a| a.closest(&format!("#{CONTAINER}")).ok().flatten().is_some())
            {
                let _ = html.focus();
            }
        }
    }

    /// The element for node `id`, and whether it is new: made anew when
    /// its role needs another tag.
    fn element(
        &mut self,
        document: &web_sys::Document,
        id: NodeId,
        role: Role,
    ) -> Option<(web_sys::Element, bool)> {
        let tag = tag(role);
        if let Some((element, _)) = self.elements.get(&id)
            && element.tag_name().eq_ignore_ascii_case(tag)
        {
            return Some((element.clone(), false));
        }
        if let Some((old, _)) = self.elements.remove(&id) {
            old.remove();
        }
        document.create_element(tag).ok().map(|e| (e, true))
    }
}

fn tag(role: Role) -> &'static str {
    match role {
        Role::Button | Role::Link | Role::CheckBox | Role::RadioButton | Role::ComboBox => "button",
        Role::Label | Role::Image => "span",
        // Real text fields, so a screen reader edits them as it edits any.
        Role::TextInput => "input",
        Role::MultilineTextInput => "textarea",
        _ => "div",
    }
}

/// Write `node`'s role, name, value, state and place on `element`.
fn describe(element: &web_sys::Element, id: NodeId, node: &Node, zoom: f64) {
    let set = |name: &str, value: Option<String>| {
        let _ = match value {
            Some(v) => element.set_attribute(name, &v),
            None => element.remove_attribute(name),
        };
    };
    set(NODE, Some(id.0.to_string()));
    let role = node.role();
    set("role", aria_role(role).map(str::to_owned));
    let field = matches!(tag(role), "input" | "textarea");
    if field {
        set_text(element, node.value().unwrap_or_default());
    }
    // A text field's value is its text, not its name.
    let name = if field {
        node.label()
    } else {
        node.label().or(node.value())
    };
    let name = name.map(str::to_owned);
    if matches!(role, Role::Label) {
        element.set_text_content(name.as_deref());
        set("aria-label", None);
    } else {
        set("aria-label", name);
    }
    set("aria-level", node.level().map(|l| l.to_string()));
    set(
        "aria-checked",
        node.toggled().map(|t| {
            match t {
                Toggled::True => "true",
                Toggled::False => "false",
                Toggled::Mixed => "mixed",
            }
            .to_owned()
        }),
    );
    set(
        "aria-disabled",
        node.is_disabled().then(|| "true".to_owned()),
    );
    set("aria-valuenow", node.numeric_value().map(|v| v.to_string()));
    set(
        "aria-valuemin",
        node.min_numeric_value().map(|v| v.to_string()),
    );
    set(
        "aria-valuemax",
        node.max_numeric_value().map(|v| v.to_string()),
    );
    set(
        "aria-valuetext",
        (role == Role::Slider)
            .then(|| node.value().map(str::to_owned))
            .flatten(),
    );
    let focusable = node.supports_action(Action::Focus) || node.supports_action(Action::Click);
    set(
        "tabindex",
        (focusable && tag(role) == "div").then(|| "0".to_owned()),
    );
    let place = node.bounds().map(|b| {
        format!(
            "left:{:.0}px;top:{:.0}px;width:{:.0}px;height:{:.0}px",
            b.x0 * zoom,
            b.y0 * zoom,
            ((b.x1 - b.x0) * zoom).max(1.0),
            ((b.y1 - b.y0) * zoom).max(1.0)
        )
    });
    set("style", place);
}

/// The ARIA role for an AccessKit role, where the element's tag does not
/// already say it.
fn aria_role(role: Role) -> Option<&'static str> {
    Some(match role {
        Role::Link => "link",
        Role::CheckBox => "checkbox",
        Role::RadioButton => "radio",
        Role::ComboBox => "combobox",
        Role::Slider => "slider",
        Role::Heading => "heading",
        Role::Image => "img",
        // A widget, named by what it shows now.
        Role::Group => "group",
        Role::Window => "main",
        _ => return None,
    })
}
