// SPDX-License-Identifier: MIT
//! `docs/figures/index.html`: the figures as a static gallery in the thesis's order — number,
//! caption, what is drawn, the data, the images inline (SVG plots, PNG images) and the glTF
//! models as links, then the tables — generated with the index page from the same registry.
//!
//! The page needs no network and no script library. A few lines of script count the images
//! that loaded once the page has: `#status` then reads "loaded N of M images". The test
//! `gallery_loads_in_headless_chromium` opens the committed page in headless Chromium (Debian
//! `chromium`) and asserts that every image loaded; without Chromium it says so and passes,
//! unless `HI_REQUIRE_PEERS=1`, when it fails.

use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::process::Command;

use super::{Figure, Table};

/// The file name of the gallery inside `docs/figures/`.
pub(crate) const GALLERY: &str = "index.html";

/// The file name of the model viewer inside `docs/figures/`.
pub(crate) const VIEWER: &str = "viewer.html";

/// The model viewer: one self-contained page (WebGL, no library, no network) that opens the
/// `.glb` named after `#model=` in its address, turns, zooms and pans it, and can draw the
/// triangles' edges; its status line says how many triangles it drew and how much of the view
/// they cover (which the tests read).
pub(crate) const VIEWER_PAGE: &str = include_str!("viewer.html");

/// The viewer's address for the model `file` of figure `number`, starting from the view its
/// render was made from.
fn viewer_link(number: (u32, u32), file: &str) -> String {
    let eye = super::renders::view(number);
    format!("{VIEWER}#model={file}&amp;up=z&amp;eye={},{},{}", eye.x, eye.y, eye.z)
}

/// `text` with `&`, `<`, `>` and `"` escaped.
fn escape(text: &str) -> String {
    let mut s = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '&' => s.push_str("&amp;"),
            '<' => s.push_str("&lt;"),
            '>' => s.push_str("&gt;"),
            '"' => s.push_str("&quot;"),
            _ => s.push(c),
        }
    }
    s
}

/// The inline markdown of the captions and tables as HTML: `code`, **bold**, *emphasis*,
/// `[label](target)` links and `![alt](image)` images (linked to themselves, at full width),
/// everything else escaped.
fn inline(text: &str) -> String {
    let mut out = String::new();
    let mut rest = text;
    while let Some(c) = rest.chars().next() {
        let after = &rest[c.len_utf8()..];
        let closing = |marker: &str| after.find(marker).map(|end| (&after[..end], end));
        match c {
            '`' => {
                if let Some((code, end)) = closing("`") {
                    let _ = write!(out, "<code>{}</code>", escape(code));
                    rest = &after[end + 1..];
                    continue;
                }
            }
            '*' if after.starts_with('*') => {
                let after = &after[1..];
                if let Some(end) = after.find("**") {
                    let _ = write!(out, "<strong>{}</strong>", inline(&after[..end]));
                    rest = &after[end + 2..];
                    continue;
                }
            }
            '*' => {
                if let Some((em, end)) = closing("*").filter(|(em, _)| !em.is_empty()) {
                    let _ = write!(out, "<em>{}</em>", inline(em));
                    rest = &after[end + 1..];
                    continue;
                }
            }
            '!' if after.starts_with('[') => {
                if let Some((alt, end)) =
                    after[1..].find("](").map(|end| (&after[1..=end], end + 1))
                    && let Some(close) = after[end + 2..].find(')')
                {
                    let src = escape(&after[end + 2..end + 2 + close]);
                    let _ = write!(
                        out,
                        "<a href=\"{src}\"><img class=\"wide\" src=\"{src}\" alt=\"{}\" \
                         loading=\"lazy\" decoding=\"async\"></a>",
                        escape(alt)
                    );
                    rest = &after[end + 2 + close + 1..];
                    continue;
                }
            }
            // A pipe escaped for a markdown table's sake is a pipe.
            '\\' if after.starts_with('|') => {
                out.push('|');
                rest = &after[1..];
                continue;
            }
            '[' => {
                if let Some((label, end)) = closing("](")
                    && let Some(close) = after[end + 2..].find(')')
                {
                    let target = &after[end + 2..end + 2 + close];
                    let _ = write!(out, "<a href=\"{}\">{}</a>", escape(target), inline(label));
                    rest = &after[end + 2 + close + 1..];
                    continue;
                }
            }
            _ => {}
        }
        out.push_str(&escape(&rest[..c.len_utf8()]));
        rest = after;
    }
    out
}

/// A markdown table (a header line, a separator, rows; cells between `|`) as an HTML table.
fn table(markdown: &str) -> String {
    let mut s = String::from("<table>\n");
    // Cells between the pipes that are not escaped (`\|` is a pipe within a cell).
    let cells = |line: &str| -> Vec<String> {
        let line = line.trim();
        let line = line.strip_prefix('|').unwrap_or(line);
        let line = if line.ends_with('|') && !line.ends_with("\\|") {
            &line[..line.len() - 1]
        } else {
            line
        };
        let mut out = Vec::new();
        let mut start = 0;
        let bytes = line.as_bytes();
        for (i, &b) in bytes.iter().enumerate() {
            if b == b'|' && (i == 0 || bytes[i - 1] != b'\\') {
                out.push(inline(line[start..i].trim()));
                start = i + 1;
            }
        }
        out.push(inline(line[start..].trim()));
        out
    };
    for (k, line) in markdown.lines().filter(|l| l.trim_start().starts_with('|')).enumerate() {
        match k {
            0 => {
                let _ = writeln!(s, "<tr><th>{}</th></tr>", cells(line).join("</th><th>"));
            }
            1 => {}
            _ => {
                let _ = writeln!(s, "<tr><td>{}</td></tr>", cells(line).join("</td><td>"));
            }
        }
    }
    s.push_str("</table>\n");
    s
}

/// The style of the page.
const STYLE: &str = "body{font-family:sans-serif;max-width:72rem;margin:auto;padding:1rem;line-height:1.4}\
section{border-top:1px solid #ccc;padding:0.5rem 0}\
.panels{display:grid;grid-template-columns:repeat(auto-fit,minmax(min(100%,22rem),1fr));gap:0.75rem;align-items:start}\
figure{margin:0;text-align:center}\
figure img{max-width:100%;height:auto;border:1px solid #eee}\
figure img[src$=\".svg\"]{width:100%;max-height:36rem;object-fit:contain}\
figcaption{font-size:0.9rem;color:#444}\
img.wide{max-width:100%;border:1px solid #eee}\
table{border-collapse:collapse;font-size:0.85rem;margin:0.5rem 0}\
td,th{border:1px solid #ccc;padding:0.2rem 0.4rem}\
code{background:#f4f4f4;padding:0 0.2rem}\
.data,.drawn,.differs{font-size:0.92rem}.differs{border-left:3px solid #d55e00;padding-left:0.5rem}\
#status{font-weight:bold}\
dialog#lightbox{max-width:96vw;max-height:96vh;border:none;padding:0.5rem;text-align:center}\
dialog#lightbox::backdrop{background:rgba(0,0,0,0.8)}\
dialog#lightbox img{max-width:92vw;max-height:82vh}\
dialog#lightbox button{float:right}";

/// The page's script, in two parts.
///
/// The lightbox: a click on an image opens it at full size in a dialog, with its caption and
/// links (a model's "turn it" opens the viewer: one click from the gallery); a click outside
/// the image, the close button or Escape closes it.
///
/// The status line: once the page has loaded, counts the images that loaded. Images load
/// lazily, as they scroll into view; with `#check` in the address (as the checks open the page)
/// every image is asked for at once first, and the count waits for all of them (at most 20 s).
const SCRIPT: &str = "window.addEventListener('load',function(){\
var box=document.getElementById('lightbox'),big=box.querySelector('img'),words=box.querySelector('p');\
document.querySelectorAll('.panels figure').forEach(function(f){var a=f.querySelector('a'),i=f.querySelector('img');\
if(!a||!i){return;}a.addEventListener('click',function(e){e.preventDefault();big.src=i.getAttribute('src');big.alt=i.alt;\
words.innerHTML=f.querySelector('figcaption').innerHTML;box.showModal();});});\
box.addEventListener('click',function(e){if(e.target===box||e.target.classList.contains('close')){box.close();}});\
var all=Array.prototype.slice.call(document.querySelectorAll('section img')),start=Date.now();\
if(location.hash==='#check'){all.forEach(function(i){i.loading='eager';});}\
function done(i){return i.complete&&(i.naturalWidth>0||i.loading==='lazy');}\
function count(){var ok=0,waiting=0;all.forEach(function(i){if(i.complete&&i.naturalWidth>0){ok++;}else if(!done(i)){waiting++;}});\
if(location.hash==='#check'&&waiting>0&&Date.now()-start<20000){setTimeout(count,100);return;}\
document.getElementById('status').textContent='loaded '+ok+' of '+all.length+' images';}\
count();});";

/// The gallery page.
pub(crate) fn gallery(
    figures: &[Figure],
    tables: &[(Table, String)],
    sizes: &BTreeMap<String, (u32, u32)>,
) -> String {
    let size = |file: &str| {
        sizes.get(file).map_or(String::new(), |(w, h)| format!(" width=\"{w}\" height=\"{h}\""))
    };
    let mut s = String::new();
    let _ = writeln!(
        s,
        "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n\
         <title>Figures of the thesis — harmonic</title>\n<style>{STYLE}</style>\n\
         <script>{SCRIPT}</script>\n</head>\n<body>\n<h1>Figures of the thesis</h1>\n\
         <p>Figures of A. Hardy, <em>Harmonic interpolation for smooth curves and surfaces</em> (2005), \
         regenerated by <code>cargo xtask figures</code>: plots as SVG, geometry images as PNG, surfaces as \
         binary glTF models, shown rendered; click an image to see it at full size with its caption, and a model's \
         \u{201c}turn it\u{201d} to turn it in the <a href=\"viewer.html\">viewer</a> (a page of this folder, no network needed; a browser reads the \
         model beside it when the folder is served, e.g. by <code>python3 -m http.server</code>, and \
         asks for the file when the page is opened from disk). The notes, the stand-in data and the \
         tables are also on the <a href=\"README.md\">index page</a>.</p>\n\
         <p id=\"status\">images not counted yet</p>\n\
         <dialog id=\"lightbox\"><button class=\"close\" type=\"button\">close</button>\
         <img alt=\"\"><p></p></dialog>"
    );
    let _ = writeln!(s, "<nav><p>");
    for f in figures {
        let label = f.label();
        let _ = write!(s, "<a href=\"#figure-{}\">{label}</a> ", label.replace('.', "-"));
    }
    let _ = writeln!(s, "</p></nav>");
    for f in figures {
        let label = f.label();
        let _ = writeln!(
            s,
            "<section id=\"figure-{}\">\n<h2>Figure {label}</h2>\n<p><em>{}</em></p>\n\
             <p class=\"drawn\">{}</p>\n<p class=\"data\">Data: {}</p>",
            label.replace('.', "-"),
            inline(f.caption),
            inline(f.drawn),
            inline(f.data)
        );
        if let Some(note) = super::differences::differs(f.number) {
            let _ =
                writeln!(s, "<p class=\"differs\">Differs from the thesis: {}</p>", inline(note));
        }
        // The panels in a grid (a figure of one panel spans it), each image linked to itself
        // at full size.
        let _ = writeln!(s, "<div class=\"panels\">");
        for (p, file, render, model) in f.entries() {
            let title = escape(&f.title(p));
            if model {
                let viewer = viewer_link(f.number, &file);
                let _ = writeln!(
                    s,
                    "<figure><a href=\"{render}\"><img src=\"{render}\" alt=\"{title}\"{} \
                     loading=\"lazy\" decoding=\"async\"></a>\
                     <figcaption>{title}: glTF model <a href=\"{file}\">{file}</a> \
                     (<a href=\"{viewer}\">turn it</a>, <a href=\"{render}\">render</a>)</figcaption></figure>",
                    size(&render)
                );
            } else {
                let _ = writeln!(
                    s,
                    "<figure><a href=\"{file}\"><img src=\"{file}\" alt=\"{title}\"{} \
                     loading=\"lazy\" decoding=\"async\"></a>\
                     <figcaption>{title}</figcaption></figure>",
                    size(&file)
                );
            }
        }
        let _ = writeln!(s, "</div>\n</section>");
    }
    if !tables.is_empty() {
        let _ = writeln!(s, "<section id=\"tables\">\n<h2>Tables</h2>");
        for (t, body) in tables {
            let _ = writeln!(
                s,
                "<h3 id=\"{}\">{}</h3>\n<p>{}</p>\n{}",
                t.anchor,
                inline(t.title),
                inline(t.about),
                table(body)
            );
        }
        let _ = writeln!(s, "</section>");
    }
    let _ = writeln!(s, "</body>\n</html>");
    s
}

/// Opens the committed gallery in `dir` in headless Chromium, as a reader would: every image
/// must load (asked for at once, with `#check`), the page's console must stay silent (no
/// script error, no message), and a screenshot of its top must show something (not one
/// colour). Returns what was checked, `None` without Chromium (an error under
/// `HI_REQUIRE_PEERS=1`).
pub(crate) fn check_gallery(dir: &std::path::Path) -> anyhow::Result<Option<String>> {
    use anyhow::{Context as _, bail};
    let Some(browser) = chromium() else {
        if std::env::var("HI_REQUIRE_PEERS").is_ok_and(|v| v == "1") {
            bail!("HI_REQUIRE_PEERS=1 but Chromium is not installed: the gallery is not checked");
        }
        return Ok(None);
    };
    let page = dir.join(GALLERY);
    let html =
        std::fs::read_to_string(&page).with_context(|| format!("reading {}", page.display()))?;
    let images = html.matches("<img ").count().saturating_sub(1); // the lightbox's
    let (status, stderr) = page_status(browser, &format!("file://{}#check", page.display()));
    let want = format!("loaded {images} of {images} images");
    if status != want {
        bail!("{GALLERY} in headless Chromium: \"{status}\", expected \"{want}\"");
    }
    let console: Vec<&str> = stderr.lines().filter(|l| l.contains(":CONSOLE")).collect();
    if !console.is_empty() {
        bail!("{GALLERY} wrote to the console:\n  {}", console.join("\n  "));
    }
    let shot = std::env::temp_dir().join(format!("harmonic-gallery-{}.png", std::process::id()));
    let profile = std::env::temp_dir().join(format!("harmonic-shot-{}", std::process::id()));
    let output = Command::new(browser)
        .args(["--headless", "--no-sandbox", "--disable-gpu", "--allow-file-access-from-files"])
        .args(["--window-size=1280,1600", "--virtual-time-budget=5000", "--hide-scrollbars"])
        .arg(format!("--user-data-dir={}", profile.display()))
        .arg(format!("--screenshot={}", shot.display()))
        .arg(format!("file://{}", page.display()))
        .output()
        .context("running Chromium")?;
    let _ = std::fs::remove_dir_all(&profile);
    let picture = image::open(&shot).with_context(|| {
        format!("Chromium wrote no screenshot: {}", String::from_utf8_lossy(&output.stderr))
    });
    let _ = std::fs::remove_file(&shot);
    let picture = picture?.to_rgb8();
    let first = picture.get_pixel(0, 0);
    let other = picture.pixels().filter(|p| *p != first).count();
    if other * 20 < picture.pixels().len() {
        bail!(
            "the screenshot of {GALLERY} is nearly blank ({other} pixels differ from the corner)"
        );
    }
    Ok(Some(format!(
        "{GALLERY}: {status} in headless Chromium, console silent, screenshot {}×{} drawn",
        picture.width(),
        picture.height()
    )))
}

/// The Chromium binary, if there is one.
pub(crate) fn chromium() -> Option<&'static str> {
    ["chromium", "chromium-browser", "google-chrome"]
        .into_iter()
        .find(|name| Command::new(name).arg("--version").output().is_ok_and(|o| o.status.success()))
}

/// Opens `url` in headless Chromium (scripts run, files beside the page readable) and
/// returns the text of the page's `#status` element once it has settled, and what
/// Chromium wrote on stderr.
pub(crate) fn page_status(browser: &str, url: &str) -> (String, String) {
    static RUN: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);
    let run = RUN.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    let profile =
        std::env::temp_dir().join(format!("harmonic-chromium-{}-{run}", std::process::id()));
    let output = Command::new(browser)
        .args([
            "--headless",
            "--no-sandbox",
            "--disable-gpu",
            "--allow-file-access-from-files",
            "--virtual-time-budget=20000",
            "--window-size=800,600",
        ])
        .arg(format!("--user-data-dir={}", profile.display()))
        .arg("--dump-dom")
        .arg(url)
        .output();
    let _ = std::fs::remove_dir_all(&profile);
    let output = match output {
        Ok(output) => output,
        Err(e) => return (format!("Chromium did not run: {e}"), String::new()),
    };
    let dom = String::from_utf8_lossy(&output.stdout);
    let status = dom
        .split("id=\"status\">")
        .nth(1)
        .and_then(|t| t.split('<').next())
        .unwrap_or("no status line")
        .to_owned();
    (status, String::from_utf8_lossy(&output.stderr).into_owned())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn inline_markdown_becomes_html() {
        assert_eq!(inline("a `x<y` b"), "a <code>x&lt;y</code> b");
        assert_eq!(inline("*It* and **bold**"), "<em>It</em> and <strong>bold</strong>");
        assert_eq!(inline("[t](u.md#a) & c"), "<a href=\"u.md#a\">t</a> &amp; c");
        assert_eq!(inline("2 * 3 = 6"), "2 * 3 = 6");
        assert_eq!(
            inline("see ![a & b](x.png) here"),
            "see <a href=\"x.png\"><img class=\"wide\" src=\"x.png\" alt=\"a &amp; b\" \
             loading=\"lazy\" decoding=\"async\"></a> here"
        );
        assert_eq!(inline("max \\|κ\\|"), "max |κ|");
        assert_eq!(
            table("| max \\|κ\\| | b |\n|---|---|\n| 1 | 2 |\n"),
            "<table>\n<tr><th>max |κ|</th><th>b</th></tr>\n<tr><td>1</td><td>2</td></tr>\n</table>\n"
        );
        assert_eq!(
            table("| a | b |\n|---|---|\n| `1` | 2 |\n"),
            "<table>\n<tr><th>a</th><th>b</th></tr>\n<tr><td><code>1</code></td><td>2</td></tr>\n</table>\n"
        );
    }

    /// Every table of the committed gallery has as many cells in each row as in its header,
    /// and no markdown escape is left in the page.
    #[test]
    fn gallery_tables_are_well_formed() {
        let page = crate::project_root().join(super::super::OUT_DIR).join(GALLERY);
        let html = std::fs::read_to_string(&page).expect("the gallery is committed");
        assert!(!html.contains("\\|"), "an escaped pipe is left in the page");
        let mut tables = 0;
        for table in html.split("<table>").skip(1) {
            let table = table.split("</table>").next().unwrap_or_default();
            let mut rows = table.split("<tr>").skip(1);
            let header = rows.next().expect("a header row").matches("<th>").count();
            for row in rows {
                assert_eq!(
                    row.matches("<td>").count(),
                    header,
                    "a row of {header} headings: {row}"
                );
            }
            tables += 1;
        }
        assert!(tables >= 8, "{tables} tables");
    }

    #[test]
    fn gallery_loads_in_headless_chromium() {
        let dir = crate::project_root().join(super::super::OUT_DIR);
        let html = std::fs::read_to_string(dir.join(GALLERY)).expect("the gallery is committed");
        let images = html.matches("<img ").count() - 1; // the lightbox's
        let panels: usize =
            super::super::registry().iter().map(|f| f.panels.len() + f.views.len()).sum();
        let in_tables: usize =
            super::super::tables().iter().map(|t| t.about.matches("![").count()).sum();
        assert_eq!(images, panels + in_tables, "one image per panel (a model's is its render)");
        assert_eq!(html.matches("loading=\"lazy\"").count(), images, "every image loads lazily");
        match check_gallery(&dir) {
            Ok(Some(summary)) => assert!(summary.contains(&format!("{images} of {images}"))),
            Ok(None) => eprintln!("gallery check skipped: Chromium is not installed"),
            Err(e) => panic!("{e:#}"),
        }
    }

    /// The viewer's status line for `viewer.html#{fragment}` in `dir`.
    fn viewer_status(browser: &str, dir: &std::path::Path, fragment: &str) -> String {
        page_status(browser, &format!("file://{}#{fragment}", dir.join(VIEWER).display())).0
    }

    /// A binary glTF of a tetrahedron with positions only (no normals), scaled by 2 and moved
    /// by a node, written here by hand (glTF 2.0 §4.4).
    fn tetrahedron_without_normals() -> Vec<u8> {
        let positions: [[f32; 3]; 4] =
            [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
        let indices: [u16; 12] = [0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3];
        let mut bin: Vec<u8> = positions.iter().flatten().flat_map(|x| x.to_le_bytes()).collect();
        bin.extend(indices.iter().flat_map(|k| k.to_le_bytes()));
        let json = format!(
            r#"{{"asset":{{"version":"2.0"}},"scene":0,"scenes":[{{"nodes":[0]}}],
"nodes":[{{"mesh":0,"scale":[2,2,2],"translation":[5,0,0]}}],
"meshes":[{{"primitives":[{{"attributes":{{"POSITION":0}},"indices":1}}]}}],
"buffers":[{{"byteLength":{}}}],
"bufferViews":[{{"buffer":0,"byteOffset":0,"byteLength":48}},{{"buffer":0,"byteOffset":48,"byteLength":24}}],
"accessors":[{{"bufferView":0,"componentType":5126,"count":4,"type":"VEC3","min":[0,0,0],"max":[1,1,1]}},
{{"bufferView":1,"componentType":5123,"count":12,"type":"SCALAR"}}]}}"#,
            bin.len()
        );
        let mut json = json.into_bytes();
        while json.len() % 4 != 0 {
            json.push(b' ');
        }
        let total = 12 + 8 + json.len() + 8 + bin.len();
        let mut glb = Vec::with_capacity(total);
        glb.extend(b"glTF");
        glb.extend(2u32.to_le_bytes());
        glb.extend(u32::try_from(total).expect("small").to_le_bytes());
        glb.extend(u32::try_from(json.len()).expect("small").to_le_bytes());
        glb.extend(b"JSON");
        glb.extend(json);
        glb.extend(u32::try_from(bin.len()).expect("small").to_le_bytes());
        glb.extend(b"BIN\0");
        glb.extend(bin);
        glb
    }

    #[test]
    fn viewer_draws_models_in_headless_chromium() {
        let required = std::env::var("HI_REQUIRE_PEERS").is_ok_and(|v| v == "1");
        let Some(browser) = chromium() else {
            assert!(!required, "HI_REQUIRE_PEERS=1 but Chromium is not installed");
            eprintln!("viewer check skipped: Chromium is not installed");
            return;
        };
        let dir = std::env::temp_dir().join(format!("harmonic-viewer-{}", std::process::id()));
        std::fs::create_dir_all(&dir).expect("a temporary folder");
        std::fs::write(dir.join(VIEWER), VIEWER_PAGE).expect("written");
        // A committed figure: the triangle count as the gltf crate reads it.
        let name = "fig-5-33b-parametric-K.glb";
        let committed = crate::project_root().join(super::super::OUT_DIR).join(name);
        std::fs::copy(&committed, dir.join(name)).expect("the figure is committed");
        let (document, _, _) = gltf::import(&committed).expect("reads");
        let triangles: usize = document
            .meshes()
            .flat_map(|m| m.primitives())
            .map(|p| p.indices().expect("indexed").count() / 3)
            .sum();
        let status = viewer_status(browser, &dir, &format!("model={name}&up=z&edges=1"));
        assert!(status.starts_with(&format!("drawn {triangles} triangles")), "{status}");
        let covered: f64 = status
            .split("covers ")
            .nth(1)
            .and_then(|t| t.split(' ').next())
            .and_then(|t| t.parse().ok())
            .expect("a coverage");
        assert!(covered > 5.0 && covered < 95.0, "{status}");
        // A cube's six quads drawn flat with their sides as lines: 12 triangles and 6 × 4
        // sides, each listed by its face.
        let cube = "fig-4-26a.glb";
        std::fs::copy(crate::project_root().join(super::super::OUT_DIR).join(cube), dir.join(cube))
            .expect("the figure is committed");
        let status = viewer_status(browser, &dir, &format!("model={cube}"));
        assert!(
            status.starts_with("drawn 12 triangles") && status.contains(", 24 lines"),
            "{status}"
        );
        // No normals: flat normals, each triangle with its own three vertices.
        std::fs::write(dir.join("tetrahedron.glb"), tetrahedron_without_normals())
            .expect("written");
        let status = viewer_status(browser, &dir, "model=tetrahedron.glb");
        assert!(status.starts_with("drawn 4 triangles, 12 vertices"), "{status}");
        // Bad input is named.
        std::fs::write(dir.join("broken.glb"), b"not a model").expect("written");
        let status = viewer_status(browser, &dir, "model=broken.glb");
        assert_eq!(status, "error: not a binary glTF file (no \"glTF\" magic)");
        let status = viewer_status(browser, &dir, "model=../secret.glb");
        assert!(status.starts_with("error:") && status.contains("not the name"), "{status}");
        let _ = std::fs::remove_dir_all(&dir);
    }
}
