"""``zero report`` (the HTML machine report) and ``zero limits --output-format svg``.

The report's findings and differences are held to what ``zero lint --machine`` and ``zero diff
--machine`` give; a real browser (Playwright driving Debian's Chromium; skipped where either is
absent) opens the page from a file: no console error, no request but the page itself, the soft
limits of every axis where the effective values put them, and a search that filters the values.
"""

from __future__ import annotations

import importlib.util
import json
import os
import re
import shutil
import subprocess
import sys
import xml.etree.ElementTree as ET
from html.parser import HTMLParser
from pathlib import Path
from typing import Any

import pytest

from conftest import FIXTURES, zero_cli
from zero.errors import ZeroError

CHROMIUM = Path("/usr/bin/chromium")
FIXTURE = FIXTURES / "machine" / "listen" / "hochlauf.lis"  # X001: work zeros outside the soft limits
LAYERED = FIXTURES / "machine-layered" / "listen" / "hochlauf.lis"
SVG = "{http://www.w3.org/2000/svg}"


def sdk(corpus: Path) -> Path:
    return corpus / "isg-sdk" / "listen" / "hochlauf.lis"


class _Elements(HTMLParser):
    """Every element's tag and attributes, in document order."""

    def __init__(self) -> None:
        super().__init__(convert_charrefs=True)
        self.elements: list[tuple[str, dict[str, str]]] = []

    def handle_starttag(self, tag: str, attrs: list[tuple[str, str | None]]) -> None:
        self.elements.append((tag, {k: v or "" for k, v in attrs}))


def elements(html: str, cls: str) -> list[dict[str, str]]:
    parser = _Elements()
    parser.feed(html)
    return [a for _, a in parser.elements if cls in a.get("class", "").split()]


def report(startup: Path, out: Path, *extra: str, cwd: Path | None = None) -> str:
    run = zero_cli("report", "--machine", str(startup), "-o", str(out), *extra, cwd=cwd,
                   env={"ZERO_DOCS_URL": ""})
    assert run.code == 0, run
    return out.read_text(encoding="utf-8")


def lint_findings(startup: Path, cwd: Path | None = None) -> list[tuple[str, int, int, str]]:
    run = zero_cli("lint", "--machine", str(startup), "--output-format", "json", cwd=cwd)
    assert run.code in (0, 1), run
    return sorted((d["path"], d["line"], d["column"], d["code"]) for d in json.loads(run.stdout))


def reported_findings(html: str) -> list[tuple[str, int, int, str]]:
    return sorted((f["data-path"], int(f["data-line"]), int(f["data-column"]), f["data-code"])
                  for f in elements(html, "finding"))


def diff_changes(old: Path | str, new: Path | str, cwd: Path | None = None) -> list[tuple[str, ...]]:
    run = zero_cli("diff", "--machine", "--output-format", "json", str(old), str(new), cwd=cwd)
    assert run.code in (0, 1), run
    return [(c["group"], c["key"], c["kind"], c["old"] or "", c["new"] or "") for c in json.loads(run.stdout)]


def reported_changes(html: str) -> list[tuple[str, ...]]:
    return [(c["data-group"], c["data-key"], c["data-kind"], c["data-old"], c["data-new"])
            for c in elements(html, "change")]


# ------------------------------------------------------------------- the same as lint and diff


@pytest.mark.slow
def test_the_findings_are_those_of_lint_machine(tmp_path: Path) -> None:
    html = report(FIXTURE, tmp_path / "machine.html")
    found = reported_findings(html)
    assert found == lint_findings(FIXTURE)
    assert sum(1 for f in found if f[3] == "X001") == 3  # G55, G58 and G159=9 outside the soft limits
    assert 'id="rule-X001"' in html and 'href="#rule-X001"' in html  # the rule's text travels in the page
    zeros = elements(html, "zero")
    outside = {(z["data-g-code"], z["data-offset"]) for z in zeros if "outside" in z["class"].split()}
    assert {("G55", "2000"), ("G159=9", "214000"), ("G58", "900")} <= outside
    clipped = [z for z in zeros if z.get("data-clipped") == "true"]
    assert [z["data-g-code"] for z in clipped] == ["G159=9"]  # far off: drawn at the edge, said in mm


@pytest.mark.slow
def test_the_sdk_demo_machine(corpus: Path, tmp_path: Path) -> None:
    html = report(sdk(corpus), tmp_path / "sdk.html")
    assert reported_findings(html) == lint_findings(sdk(corpus))
    assert len(elements(html, "axis")) == 4  # X, Y, Z of channel 0, and axis 4 (no channel maps it)
    assert "<script src" not in html and '<link rel="stylesheet"' not in html
    assert "http://" not in html and "https://" not in html  # nothing to fetch


@pytest.mark.slow
def test_rule_links_go_to_the_documentation_site_where_one_is_named(tmp_path: Path) -> None:
    run = zero_cli("report", "--machine", str(FIXTURE), "-o", str(tmp_path / "m.html"),
                   env={"ZERO_DOCS_URL": "https://zero.example/docs"})
    assert run.code == 0, run
    html = (tmp_path / "m.html").read_text(encoding="utf-8")
    assert 'href="https://zero.example/docs/rules/X001/"' in html and 'id="rule-X001"' not in html


@pytest.mark.slow
def test_the_differences_are_those_of_diff_machine(tmp_path: Path) -> None:
    html = report(FIXTURE, tmp_path / "m.html", "--against", str(LAYERED))
    changes = reported_changes(html)
    assert changes and changes == diff_changes(LAYERED, FIXTURE)
    assert elements(html, "old-range")  # the golden machine's soft limits drawn under the changed ones
    deltas = {(c["data-group"].split(":")[0], c["data-key"]): c for c in elements(html, "change")}
    table = html[html.index('id="diff-table"'):html.index("</table>", html.index('id="diff-table"'))]
    assert "um/s" not in table and "mdeg/s" not in table  # µm/s, m/min: units as an engineer reads them
    for (group, key), _ in deltas.items():  # a length of a known axis is in mm or °, never "mm or °"
        row = html[html.index(f'data-key="{key}"', html.index('id="diff-table"')):]
        delta = row[row.index('class="num delta">') + 19:row.index("</td>", row.index('class="num delta">'))]
        if group.startswith("axis ") or key.endswith((".laenge", ".radius")):
            assert "mm or °" not in delta, (group, key, delta)


@pytest.mark.slow
def test_the_fleet_drift_is_that_of_diff_fleet(tmp_path: Path) -> None:
    """`zero report --fleet`: the fleet section is what `zero diff --fleet` reports with the
    report's machine golden (four copies of the clean machine, `swe_pos` of X changed on two)."""
    import shutil

    clean = FIXTURES / "machine-clean"
    shutil.copytree(clean, tmp_path / "golden")
    for name in ("m1", "m2", "m3", "m4"):
        shutil.copytree(clean, tmp_path / "fleet" / name)
    for name in ("m2", "m4"):
        axis = tmp_path / "fleet" / name / "listen" / "achse_x.lis"
        axis.write_text(axis.read_text().replace("15000000", "16000000"))
    golden = tmp_path / "golden" / "listen" / "hochlauf.lis"
    html = report(golden, tmp_path / "g.html", "--fleet", str(tmp_path / "fleet"), "-j", "1")
    run = zero_cli("diff", "--fleet", str(golden), str(tmp_path / "fleet"), "--output-format", "json", "-j", "1")
    assert run.code == 1, run
    expected = [(p["key"], p["id"] or "", str(p["count"]), str(p["of"])) for p in json.loads(run.stdout)["parameters"]]
    drift = [(d["data-key"], d["data-id"], d["data-count"], d["data-of"]) for d in elements(html, "drift")]
    assert drift == expected == [("kenngr.swe_pos", "P-AXIS-00178", "2", "4")]
    assert "m2, m4" in html
    nav = html[html.index("<nav>"):html.index("</nav>")]
    assert "<section" not in nav and 'href="#fleet"' in nav  # its own section, linked (it was drawn inside <nav>)
    assert html.index('<section id="fleet">') > html.index("</nav>")
    assert 'href="#fleet" data-card="fleet"' in html  # the summary card leads to it


def _git(repo: Path, *args: str) -> None:
    env = {**os.environ, "GIT_AUTHOR_NAME": "t", "GIT_AUTHOR_EMAIL": "t@example.org", "GIT_COMMITTER_NAME": "t",
           "GIT_COMMITTER_EMAIL": "t@example.org", "GIT_CONFIG_GLOBAL": os.devnull, "GIT_CONFIG_NOSYSTEM": "1"}
    subprocess.run(["git", *args], cwd=repo, check=True, capture_output=True, env=env)


@pytest.mark.slow
@pytest.mark.skipif(shutil.which("git") is None, reason="git is not installed")
def test_against_a_git_revision(tmp_path: Path) -> None:
    repo = tmp_path / "repo"
    shutil.copytree(FIXTURE.parent, repo / "listen")
    _git(repo, "init", "-q")
    _git(repo, "add", "-A")
    _git(repo, "commit", "-qm", "machine")
    axis = repo / "listen" / "achse_x.lis"
    axis.write_text(axis.read_text().replace("15000000", "12000000"))
    # a filter the repository configures never runs: `git cat-file blob` reads the stored bytes
    (repo / ".gitattributes").write_text("*.lis filter=evil\n")
    _git(repo, "config", "filter.evil.smudge", f"touch {tmp_path / 'ran'}")
    html = report(Path("listen/hochlauf.lis"), repo / "m.html", "--against", "HEAD", cwd=repo)
    old = tmp_path / "old"
    shutil.copytree(FIXTURE.parent, old / "listen")
    changes = reported_changes(html)
    assert changes == diff_changes(old / "listen" / "hochlauf.lis", "listen/hochlauf.lis", cwd=repo)
    assert [c[1:] for c in changes] == [("kenngr.swe_pos", "changed", "15000000", "12000000")]
    old_bar = elements(html, "old-range")
    assert [(b["data-swe-neg"], b["data-swe-pos"]) for b in old_bar] == [("-1000", "1500")]
    assert not (tmp_path / "ran").exists()
    bad = zero_cli("report", "--machine", "listen/hochlauf.lis", "--against", "no-such-rev", cwd=repo)
    assert bad.code == 2 and "not a revision" in bad.stderr


def test_without_jinja2_the_report_says_how_to_get_it(monkeypatch: pytest.MonkeyPatch) -> None:
    from zero.output.report import Link, MachineReport, render_report

    monkeypatch.setitem(sys.modules, "jinja2", None)
    empty = MachineReport("t", Link("s", None), ".", "now", [], [], [], [], [], [], [], [], None)
    with pytest.raises(ZeroError, match=r"zero-lint\[report\]"):
        render_report(empty)


@pytest.mark.slow
def test_values_are_escaped(tmp_path: Path) -> None:
    machine = tmp_path / "m"
    shutil.copytree(FIXTURE.parent, machine / "listen")
    axis = machine / "listen" / "achse_x.lis"
    axis.write_text(axis.read_text().replace("Ende", "kenngr.bezeichnung <script>alert(1)</script>\nEnde"))
    html = report(machine / "listen" / "hochlauf.lis", tmp_path / "m.html")
    assert "<script>alert" not in html and "&lt;script&gt;alert(1)&lt;/script&gt;" in html


# ------------------------------------------------------------------------- zero limits as SVG


@pytest.mark.slow
def test_limits_svg_is_one_well_formed_picture_with_a_group_per_axis() -> None:
    run = zero_cli("limits", "--machine", str(FIXTURE), "--output-format", "svg")
    assert run.code == 0, run
    root = ET.fromstring(run.stdout)
    assert root.tag == f"{SVG}svg"
    groups = [g for g in root.findall(f"{SVG}g") if "axis" in g.get("class", "").split()]
    rows = json.loads(zero_cli("limits", "--machine", str(FIXTURE), "--output-format", "json").stdout)["limits"]
    channel_axes = {(r["channel"], r["axis"]): r for r in rows}
    assert len(groups) == len(channel_axes) == 4
    assert [g.get("data-axis") for g in groups] == ["X", "Y", "C", "V"]
    x = groups[0]
    assert (x.get("data-swe-neg"), x.get("data-swe-pos")) == ("-1000", "1500")
    assert not root.findall(f".//{SVG}image") and "href" not in run.stdout  # standalone: nothing to fetch


# ------------------------------------------------------------------------------ the browser


def _browser_missing() -> str | None:
    if importlib.util.find_spec("playwright") is None:
        return "playwright is not installed (pip install playwright; never `playwright install`)"
    if not CHROMIUM.is_file():
        return f"no Chromium at {CHROMIUM} (apt-get install chromium)"
    return None


def _effective_limits(startup: Path) -> dict[int, tuple[float, float]]:
    """Logical axis number → the soft limits in mm or degrees, as `zero explain` gives them."""
    run = zero_cli("explain", "kenngr.swe_neg", "kenngr.swe_pos", "--machine", str(startup), "--output-format", "json")
    assert run.code == 0, run
    out: dict[int, tuple[float, float]] = {}
    for scope in json.loads(run.stdout)["scopes"]:
        if not scope["scope"].startswith("axis "):
            continue
        nr = int(scope["scope"].split()[1])
        values = {v["key"]: int(v["value"]) / 10_000 for v in scope["values"]}
        out.setdefault(nr, (values["kenngr.swe_neg"], values["kenngr.swe_pos"]))  # the first list wins
    return out


def _check_in_browser(page: Any, html: Path, startup: Path, shots: Path, name: str) -> None:
    requests: list[str] = []
    problems: list[str] = []
    page.on("request", lambda r: requests.append(r.url))
    page.on("console", lambda m: problems.append(f"{m.type}: {m.text}") if m.type in ("error", "warning") else None)
    page.on("pageerror", lambda e: problems.append(f"page error: {e}"))
    page.goto(html.as_uri())
    page.wait_for_load_state("load")
    assert requests == [html.as_uri()]  # nothing but the page itself
    assert problems == []

    expected = _effective_limits(startup)
    axes = page.eval_on_selector_all("g.axis", """gs => gs.map(g => {
        const neg = g.querySelector('.swe-neg'), pos = g.querySelector('.swe-pos');
        const box = el => el.getBoundingClientRect();
        return {nr: +g.dataset.logNr, linear: g.classList.contains('linear'), modulo: g.dataset.modulo === 'true',
                neg: +g.dataset.sweNeg, pos: +g.dataset.swePos, lo: +g.dataset.domainLo, hi: +g.dataset.domainHi,
                x0: +g.dataset.x0, x1: +g.dataset.x1,
                xneg: neg ? +neg.getAttribute('x1') : null, xpos: pos ? +pos.getAttribute('x1') : null,
                barneg: neg ? +neg.dataset.value : null, barpos: pos ? +pos.dataset.value : null,
                left: neg ? box(neg).left : null, right: pos ? box(pos).left : null};
    })""")
    assert axes
    for ax in axes:
        assert (ax["neg"], ax["pos"]) == pytest.approx(expected[ax["nr"]]), ax
        if ax["modulo"]:
            continue
        assert (ax["barneg"], ax["barpos"]) == pytest.approx(expected[ax["nr"]]), ax
        if ax["linear"]:
            def at(v: float, a: dict[str, Any] = ax) -> float:
                return float(a["x0"] + (v - a["lo"]) / (a["hi"] - a["lo"]) * (a["x1"] - a["x0"]))
            assert ax["xneg"] == pytest.approx(at(ax["neg"]), abs=0.01), ax
            assert ax["xpos"] == pytest.approx(at(ax["pos"]), abs=0.01), ax
            assert ax["left"] < ax["right"]  # drawn: the negative limit left of the positive one

    total = page.locator("#value-table tbody tr").count()
    assert page.is_checked("#filter-differs")  # --values changed: the page opens with what it prints
    page.uncheck("#filter-differs")
    page.fill("#search", "swe_pos")
    visible = page.locator("#value-table tbody tr:visible")
    shown = visible.count()
    assert 0 < shown < total
    assert all("swe_pos" in t for t in visible.all_inner_texts())
    assert page.inner_text("#value-count") == str(shown)
    page.fill("#search", "")
    page.check("#filter-differs")
    differing = page.eval_on_selector_all("#value-table tbody tr:not([hidden])", "rs => rs.map(r => r.dataset.printed)")
    assert differing and set(differing) == {"1"} and len(differing) < total
    page.uncheck("#filter-differs")
    page.select_option("#filter-origin", "catalogue default")
    origins = page.eval_on_selector_all("#value-table tbody tr:not([hidden])", "rs => rs.map(r => r.dataset.origin)")
    assert set(origins) == {"catalogue default"}
    page.select_option("#filter-origin", "")

    page.emulate_media(media="print")  # printing loses nothing: the rules' texts open
    rule = page.locator("details.rule pre").first
    assert rule.is_visible()
    page.emulate_media(media="screen")

    page.evaluate("window.scrollTo(0, 0)")
    home = shots / f"{name}-home.png"
    page.screenshot(path=str(home))
    pictures = shots / f"{name}-axes.png"
    page.locator("#axes").screenshot(path=str(pictures))
    page.fill("#search", "swe_")  # the whole page, its value table searched down to the soft limits
    whole = shots / f"{name}-page.png"
    page.screenshot(path=str(whole), full_page=True)
    print(f"screenshots: {home} {pictures} {whole}")


@pytest.mark.slow
@pytest.mark.parametrize("name", ["fixture", "sdk"])
def test_the_report_in_a_real_browser(name: str, tmp_path: Path, request: pytest.FixtureRequest) -> None:
    missing = _browser_missing()
    if missing:
        pytest.skip(missing)
    from playwright.sync_api import sync_playwright

    startup = FIXTURE if name == "fixture" else sdk(request.getfixturevalue("corpus"))
    html = tmp_path / f"{name}.html"
    report(startup, html)
    with sync_playwright() as p:
        browser = p.chromium.launch(executable_path=str(CHROMIUM), args=["--no-sandbox"])
        try:
            page = browser.new_page(viewport={"width": 1280, "height": 900})
            _check_in_browser(page, html, startup, tmp_path, name)
        finally:
            browser.close()


# ------------------------------------------------------------------- units, corrections, marks


def test_values_in_engineering_units() -> None:
    from zero.output.report import in_engineering

    assert in_engineering(("0.1um", "0.1mdeg"), 10_400_000, rotary=False) == "1,040 mm"
    assert in_engineering(("0.1um", "0.1mdeg"), 3_600_000, rotary=True) == "360 °"
    assert in_engineering(("0.1um", "0.1mdeg"), 5_000, rotary=None) == "0.5 mm or 0.5 °"  # the axis not known
    assert in_engineering(("um/s", "mdeg/s"), 2_000_000, rotary=False) == "120 m/min"
    assert in_engineering(("um/s", "mdeg/s"), 1_000, rotary=True) == "60 °/min"
    assert in_engineering(("us",), 250, rotary=None) == "250 µs"
    assert in_engineering(("0.1%",), 1000, rotary=None) == "100 %"
    assert in_engineering(("increments",), 5, rotary=None) is None  # no unit an engineer converts


def test_deltas_in_engineering_units() -> None:
    from zero.diff import Change
    from zero.output.report import delta_in_engineering

    assert delta_in_engineering(Change("kenngr.swe_pos", "P-AXIS-00178", "changed", "1", "2", "mm or °", 500.0),
                                rotary=False) == "+500 mm"
    assert delta_in_engineering(Change("k", None, "changed", "1", "2", "mm or °", -5.0), rotary=True) == "-5 °"
    assert delta_in_engineering(Change("k", None, "changed", "1", "2", "um/s, mdeg/s", 100_000), rotary=False) \
        == "+6 m/min"
    assert delta_in_engineering(Change("k", None, "changed", "1", "2", None, None), rotary=False) == ""


def test_the_documented_correction_is_the_value_the_controller_uses() -> None:
    from zero.catalog.registry import load_registry
    from zero.output.report import corrects

    registry = load_registry()
    assert corrects("K093", "P-AXIS-00512", registry) == {"P-AXIS-00512": "1"}  # P-ERR-110580: corrected to 1
    default = next(c for c in __import__("zero.rules.startup", fromlist=["CHECKS"]).CHECKS
                   if c.correction == "default")
    used = corrects(default.code, default.params[0], registry)
    assert list(used) == [default.params[0]] and used[default.params[0]].endswith("(the default)")
    aborts = next(c for c in __import__("zero.rules.startup", fromlist=["CHECKS"]).CHECKS if c.correction == "abort")
    assert corrects(aborts.code, aborts.params[0], registry) == {}  # nothing is used: the start-up stops
    assert corrects("M005", "P-AXIS-00705", registry) == {}  # no documented correction: no value claimed


@pytest.mark.slow
def test_monitoring_marks_on_the_fixture_machine(tmp_path: Path) -> None:
    machine = tmp_path / "m"
    shutil.copytree(FIXTURE.parent, machine / "listen")
    axis = machine / "listen" / "achse_x.lis"
    axis.write_text(axis.read_text().replace("Ende", "kenngr.swe_check 0\nEnde"))
    html = report(machine / "listen" / "hochlauf.lis", tmp_path / "m.html")
    groups = [g for g in elements(html, "axis") if g.get("data-axis") == "X"]
    assert groups and groups[0]["data-monitoring"] == "off" and "monitoring-off" in groups[0]["class"]
    assert "soft-limit monitoring OFF (kenngr.swe_check = 0)" in html
    marks = elements(html, "monitor-off")
    assert marks and any(m.get("data-monitoring") == "off" for m in marks)
    assert 'data-count="unmonitored">1<' in html


@pytest.mark.slow
def test_a_value_outside_its_range_on_an_axis_list_is_shown_as_the_kernel_limits_it(tmp_path: Path) -> None:
    """R005 on an axis list: the kernel limits the value to the permissible maximum (P-ERR-1001138,
    evidence.toml); the row says 100 for 150, linked to the finding that says so."""
    machine = tmp_path / "m"
    shutil.copytree(FIXTURE.parent, machine / "listen")
    axis = machine / "listen" / "achse_x.lis"
    axis.write_text(axis.read_text().replace("Ende", "handbetrieb.ipo.hb_proz_v_max 150\nEnde"))
    html = report(machine / "listen" / "hochlauf.lis", tmp_path / "m.html")
    rows = [r for r in elements(html, "corrected")]
    assert [r.get("data-used") for r in rows] == ["100 (the permissible maximum)"]
    anchor = html[html.index('class="uses"'):].split('href="#', 1)[1].split('"', 1)[0]
    finding = [f for f in elements(html, "finding") if f.get("id") == anchor]
    assert finding and finding[0]["data-code"] == "R005"


def test_a_twincat_project_names_each_lists_item_and_an_axis_drive_type(tmp_path: Path) -> None:
    """Issue 37: the item each list of a TwinCAT project comes from, and an axis's DriveType and
    Spindle as the project writes them, stand in the structure; a machine of plain files has no such
    column."""
    html = report(FIXTURES / "twincat" / "project" / "Maschine.tsproj", tmp_path / "p.html")
    cells = re.findall(r'<td class="twincat">([^<]*)</td>', html)
    assert "X_Achse · DriveType 4 · Spindle false" in cells
    assert "C_Spindel · DriveType 4 · Spindle true" in cells
    assert "<th>TwinCAT item</th>" in html
    plain = report(FIXTURE, tmp_path / "f.html")
    assert "TwinCAT item" not in plain and 'class="twincat"' not in plain
