// Checks a grading report from inside the browser (instructor/scripts/test-report-browser.sh).
// The script puts this at the top of <head> in a copy of report.html; on `load`
// it appends its verdict, one finding a line, to the page (a pre element with
// id report-check), which `chromium --dump-dom` prints:
//   images N loaded K shown S   N <img> elements, K of them decoded with naturalWidth > 0,
//                               S of them laid out in a box of some size
//   image-failed ALT: SRC       a picture that did not load
//   fetch status=S URL          a resource fetched or attempted (Resource Timing), not data: nor this
//                               file; S is its HTTP status, 0 when it was not reached
//   link TAG ATTRIBUTE: URL     an attribute pointing outside (not data: nor #)
//   css WHERE: URL              a url(...) or @import in a style sheet or style attribute, not data: nor #
//   height PIXELS               the page's full height at the window's width, for the screenshot
//   done
"use strict";
performance.setResourceTimingBufferSize(100000); // never drop an entry
const fetched = [];
new PerformanceObserver((list) => fetched.push(...list.getEntries())).observe({ type: "resource", buffered: true });

window.addEventListener("load", () => {
    const lines = [];
    const short = (text) => (text.length > 80 ? text.slice(0, 80) + "..." : text);
    const outside = (url) => !/^\s*(data:|#|$)/i.test(url);

    const images = Array.from(document.images);
    const loaded = images.filter((img) => img.complete && img.naturalWidth > 0);
    const shown = images.filter((img) => img.offsetWidth > 0 && img.offsetHeight > 0);
    lines.push(`images ${images.length} loaded ${loaded.length} shown ${shown.length}`);
    for (const img of images)
        if (!loaded.includes(img)) lines.push(`image-failed ${img.alt || "(no alt)"}: ${short(img.getAttribute("src") || "")}`);

    const entries = new Map([...fetched, ...performance.getEntriesByType("resource")].map((entry) => [entry.name, entry]));
    const self = location.href.split("#")[0];
    for (const [name, entry] of entries)
        if (!name.startsWith("data:") && name.split("#")[0] !== self) lines.push(`fetch status=${entry.responseStatus ?? "?"} ${short(name)}`);

    const urlAttributes = ["src", "href", "srcset", "poster", "data", "action", "formaction", "background", "xlink:href", "ping", "manifest", "cite", "longdesc"];
    const cssUrls = (text) => Array.from(text.matchAll(/url\(\s*(['"]?)(.*?)\1\s*\)|@import\s+(['"])(.*?)\3/gi), (m) => m[2] ?? m[4]);
    for (const element of document.querySelectorAll("*")) {
        if (element.id === "report-check") continue;
        for (const attribute of element.attributes) {
            const name = attribute.name.toLowerCase();
            if (name === "style") {
                for (const url of cssUrls(attribute.value))
                    if (outside(url)) lines.push(`css ${element.localName} style: ${short(url)}`);
            } else if (urlAttributes.includes(name) && outside(attribute.value)) {
                lines.push(`link ${element.localName} ${name}: ${short(attribute.value)}`);
            }
        }
    }
    for (const sheet of document.styleSheets) {
        if (sheet.href && outside(sheet.href)) lines.push(`link stylesheet href: ${short(sheet.href)}`);
        let rules = [];
        try { rules = Array.from(sheet.cssRules); } catch { lines.push(`css style sheet: unreadable (${short(sheet.href || "inline")})`); }
        for (const rule of rules)
            for (const url of cssUrls(rule.cssText)) if (outside(url)) lines.push(`css style sheet: ${short(url)}`);
    }

    lines.push(`height ${document.documentElement.scrollHeight}`);
    lines.push("done");
    const verdict = document.createElement("pre");
    verdict.id = "report-check";
    verdict.textContent = "\n" + lines.join("\n") + "\n";
    document.body.append(verdict);
});
