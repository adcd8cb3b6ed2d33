//! The page around the lab in a browser (docs/design.md §5.8): its address's fragment (the
//! view links), a file picker and downloads in place of paths on a disk, its clock, and the
//! elements the page and the browser test read. Browser-only: nothing here exists on the
//! desktop.

use std::cell::RefCell;
use std::rc::Rc;

use wasm_bindgen::JsCast;
use wasm_bindgen::prelude::*;

fn document() -> Option<web_sys::Document> {
    web_sys::window()?.document()
}

/// Milliseconds since the page's navigation started (the browser's `performance.now()`).
pub fn now_ms() -> f64 {
    web_sys::window()
        .and_then(|w| w.performance())
        .map_or(0.0, |p| p.now())
}

/// The page address's fragment, without its `#`.
pub fn fragment() -> String {
    web_sys::window()
        .and_then(|w| w.location().hash().ok())
        .map(|h| h.trim_start_matches('#').to_string())
        .unwrap_or_default()
}

/// Puts `fragment` in the page's address in place of its own (no new history entry), and
/// gives the whole address.
pub fn set_fragment(fragment: &str) -> Option<String> {
    let window = web_sys::window()?;
    let location = window.location();
    let base = location.href().ok()?;
    let base = base.split('#').next().unwrap_or_default();
    let url = format!("{base}#{fragment}");
    window
        .history()
        .ok()?
        .replace_state_with_url(&JsValue::NULL, "", Some(&url))
        .ok()?;
    Some(url)
}

/// Writes `text` into the page's element `id` (where the page has one).
pub fn write_element(id: &str, text: &str) {
    if let Some(el) = document().and_then(|d| d.get_element_by_id(id)) {
        el.set_text_content(Some(text));
    }
}

/// Offers `bytes` to the user as a download named `name`.
pub fn download(name: &str, bytes: &[u8], mime: &str) -> Result<(), String> {
    let why = |e: JsValue| format!("the browser refused the download of {name}: {e:?}");
    let document = document().ok_or("no page")?;
    let array = js_sys::Uint8Array::from(bytes);
    let parts = js_sys::Array::of1(&array);
    let options = web_sys::BlobPropertyBag::new();
    options.set_type(mime);
    let blob =
        web_sys::Blob::new_with_u8_array_sequence_and_options(&parts, &options).map_err(why)?;
    let url = web_sys::Url::create_object_url_with_blob(&blob).map_err(why)?;
    let anchor: web_sys::HtmlAnchorElement = document
        .create_element("a")
        .map_err(why)?
        .dyn_into()
        .map_err(|_| "no anchor element".to_string())?;
    anchor.set_href(&url);
    anchor.set_download(name);
    anchor.click();
    let _ = web_sys::Url::revoke_object_url(&url);
    Ok(())
}

/// Files the user picked, named and read, once the browser has read them all.
pub type Picked = Rc<RefCell<Option<Vec<(String, Vec<u8>)>>>>;

/// Opens the browser's file picker for files matching `accept` (`multiple`: more than one,
/// as a DDS pair is); what is picked arrives in the returned cell, and `repaint` is woken.
pub fn pick(accept: &str, multiple: bool, repaint: egui::Context) -> Result<Picked, String> {
    let why = |e: JsValue| format!("the browser's file picker: {e:?}");
    let document = document().ok_or("no page")?;
    let input: web_sys::HtmlInputElement = document
        .create_element("input")
        .map_err(why)?
        .dyn_into()
        .map_err(|_| "no input element".to_string())?;
    input.set_type("file");
    input.set_accept(accept);
    input.set_multiple(multiple);
    let picked: Picked = Rc::new(RefCell::new(None));
    let into = picked.clone();
    let source = input.clone();
    let on_change = Closure::once(move || {
        let Some(list) = source.files() else {
            return;
        };
        let files: Vec<web_sys::File> = (0..list.length()).filter_map(|k| list.get(k)).collect();
        wasm_bindgen_futures::spawn_local(async move {
            let mut read = Vec::new();
            for file in files {
                let buffer = wasm_bindgen_futures::JsFuture::from(file.array_buffer()).await;
                if let Ok(buffer) = buffer {
                    read.push((file.name(), js_sys::Uint8Array::new(&buffer).to_vec()));
                }
            }
            *into.borrow_mut() = Some(read);
            repaint.request_repaint();
        });
    });
    input.set_onchange(Some(on_change.as_ref().unchecked_ref()));
    // The input lives as long as the page would keep it; its handler with it.
    on_change.forget();
    input.click();
    Ok(picked)
}
