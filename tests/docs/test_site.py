"""The documentation site: every rule and every parameter has its generated page (and every page
its rule or parameter), the site builds with warnings as errors, and a real browser finds things
in it (Playwright driving Debian's Chromium; skipped where either is absent)."""

from __future__ import annotations

import functools
import http.server
import importlib.util
import os
import re
import shutil
import subprocess
import sys
import threading
import time
from collections.abc import Callable, Iterator
from pathlib import Path
from types import ModuleType

import pytest

from conftest import ROOT, corpus_dir, script_module
from zero.catalog.registry import Registry
from zero.output import docs
from zero.rules import RULES

CHROMIUM = Path("/usr/bin/chromium")
CATALOGUE = corpus_dir() / "isg-sdk" / "meta-data" / "CncParaDesc.xml"  # the vendor's, read at build time only
QUIET = {"NO_MKDOCS_2_WARNING": "1", "DISABLE_MKDOCS_2_WARNING": "true"}  # the plugins' banners, not warnings


@functools.cache
def generator() -> ModuleType:
    """docs/gen_pages.py, imported as a module (mkdocs-gen-files runs it as a script)."""
    return script_module(ROOT / "docs" / "gen_pages.py")


@functools.cache
def generated() -> dict[str, Callable[[], str]]:
    pages: dict[str, Callable[[], str]] = generator().pages()
    return pages


# --------------------------------------------------------------------------- the generated pages


def test_the_pages_generate_without_click_installed() -> None:
    """typer 0.29 carries its own click and installs none: the README's ``pip install -e '.[test]'``
    has no click, so the page generator must not import it (issue 35: 9 failures on a fresh clone)."""
    code = ("import sys, importlib.util; sys.modules['click'] = None\n"
            f"spec = importlib.util.spec_from_file_location('gen_pages', {str(ROOT / 'docs' / 'gen_pages.py')!r})\n"
            "m = importlib.util.module_from_spec(spec); spec.loader.exec_module(m)\n"
            "print(len(m.pages()['commands/lint.md']()))")
    run = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=300, cwd=ROOT)
    assert run.returncode == 0, run.stderr[-3000:]
    assert int(run.stdout) > 1000


def test_every_rule_has_a_page_and_every_rule_page_a_rule() -> None:
    pages = {p.removeprefix("rules/").removesuffix(".md") for p in generated() if p.startswith("rules/")}
    assert pages - {"index"} == set(RULES)


def test_every_parameter_has_a_page_and_every_parameter_page_a_parameter(registry: Registry) -> None:
    kinds = {s.kind for s in registry.specs.values()}
    pages = {p.removeprefix("parameters/").removesuffix(".md") for p in generated() if p.startswith("parameters/")}
    assert pages - {"index", "SUMMARY"} - kinds == set(registry.specs)
    assert len(registry.specs) >= 1766


def test_every_command_has_a_page() -> None:
    import typer.main

    from zero.cli.app import app

    group = typer.main.get_command(app)
    pages = {p.removeprefix("commands/").removesuffix(".md") for p in generated() if p.startswith("commands/")}
    shown = {n for n, c in group.commands.items() if not c.hidden}  # type: ignore[attr-defined]
    assert pages - {"index", "SUMMARY"} == shown


def test_the_hand_written_pages_the_nav_names_exist() -> None:
    import yaml

    config = yaml.safe_load((ROOT / "mkdocs.yml").read_text(encoding="utf-8"))

    def leaves(items: list[object]) -> Iterator[str]:
        for item in items:
            for value in (item.values() if isinstance(item, dict) else [item]):
                if isinstance(value, list):
                    yield from leaves(value)
                else:
                    yield str(value)

    made = set(generated())
    for page in leaves(config["nav"]):
        if page.endswith("/"):
            assert f"{page}SUMMARY.md" in made, page
        else:
            assert page in made or (ROOT / "docs" / page).is_file(), page


def test_a_rule_page_says_everything() -> None:
    page = generated()["rules/R006.md"]()
    assert page.startswith("# R006 range-reference")
    default = RULES["R006"].severity.label  # the evidence decides it (issue 36), not this test
    assert f"| Default severity | {default} |" in page and "## Why it matters on the machine" in page
    assert "`fixtures/rules/R006/fail.lis`" in page and 'hl_lines="4"' in page
    assert "getriebe[0].dynamik.a_emergency 5000" in page  # the failing list
    assert "getriebe[0].dynamik.a_emergency 4000" in page  # the passing one
    assert re.search(r"fail\.lis:4:33: R006 (error|warning|info) 5000 violates", page)  # what zero reports on it
    assert "offers no automatic fix" in page


def test_a_kernel_rule_page_has_its_error_number_and_parameters() -> None:
    page = generated()["rules/K031.md"]()
    assert "`P-ERR-110051`" in page and "`fixtures/startup/110051/fail.lis`" in page
    assert "[P-AXIS-00015](../parameters/P-AXIS-00015.md)" in page


def test_fixes_and_their_safety_come_from_the_failing_example() -> None:
    assert "**unsafe**" in generated()["rules/R001.md"]() and "--unsafe-fixes" in generated()["rules/R001.md"]()
    assert "**safe**" in generated()["rules/S005.md"]()


def test_machine_and_program_rules_show_the_fixture_machine() -> None:
    x001 = generated()["rules/X001.md"]()
    assert "`fixtures/machine/listen/nullp.lis`" in x001 and "X001 warning" in x001
    assert "`fixtures/machine-clean/listen/nullp.lis`" in x001
    assert "`fixtures/programs/bad.nc`" in generated()["rules/N001.md"]()
    assert "no example list" in generated()["rules/F001.md"]()  # said, not made up


def test_a_parameter_page_says_what_checks_it() -> None:
    page = generated()["parameters/P-AXIS-00178.md"]()
    assert page.startswith("# P-AXIS-00178 kenngr.swe\\_pos")
    assert "| key | `kenngr.swe_pos` |" in page and "| default | `100000000` |" in page
    assert "[P-AXIS-00177](../parameters/P-AXIS-00177.md) &lt; swe\\_pos" in page  # the range, linked
    assert "[R006](../rules/R006.md)" in page and "[K042](../rules/K042.md)" in page
    assert "[axis parameter list](../parameters/AXIS.md)" in page


def test_param_checks(registry: Registry) -> None:
    checks = docs.param_checks(registry)
    assert set(checks) == set(registry.specs)
    assert {c.code for c in checks["P-AXIS-00152"]} >= {"R006"}  # its prose range, evaluated
    restart = next(s.id for s in registry.specs.values() if s.restart)
    assert "U001" in {c.code for c in checks[restart]}
    ranged = next(s for s in registry.specs.values()
                  if (r := registry.range_of(s)) is not None and not r.refs)
    assert "R005" in {c.code for c in checks[ranged.id]}


def test_markdown_helpers() -> None:
    assert docs.md_text("a < b | *c* [d] `e` x_y") == "a &lt; b \\| \\*c\\* \\[d\\] \\`e\\` x\\_y"
    assert docs.md_code("a|b") == "`a\\|b`"
    text, lines = docs.shown_list(b"a 1\r\nb\x00 2\n\xe4\n")
    assert text.split("\n") == ["a 1\\r", "b\\x00 2", "\\xe4"] and lines == 3
    md = docs.explanation_markdown("What it checks: one thing.\n\nWhy it matters on the machine: x\nFix: y")
    assert "## What it checks\n\nOne thing." in md and "## Fix\n\nY" in md


# --------------------------------------------------------------------------------- the built site


def _mkdocs_missing() -> str | None:
    for module in ("mkdocs", "material", "mkdocs_gen_files", "mkdocs_literate_nav"):
        if importlib.util.find_spec(module) is None:
            return f"{module} is not installed (pip install -e '.[docs]')"
    return None


@pytest.fixture(scope="module")
def site(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """The site built once with ``mkdocs build --strict`` (warnings are errors)."""
    reason = _mkdocs_missing()
    if reason:
        pytest.skip(reason)
    out = tmp_path_factory.mktemp("site")
    env = {**os.environ, **QUIET}
    if CATALOGUE.is_file():  # built as a user with the catalogue builds it: its German names as search terms
        env["ZERO_PARAM_DESC"] = str(CATALOGUE)
    start = time.perf_counter()
    run = subprocess.run([sys.executable, "-m", "mkdocs", "build", "--strict", "--site-dir", str(out)],
                         cwd=ROOT, capture_output=True, text=True, env=env, timeout=600)
    took = time.perf_counter() - start
    assert run.returncode == 0, run.stderr[-5000:]
    pages = sum(1 for _ in out.rglob("index.html"))
    print(f"\nmkdocs build --strict: {took:.1f} s, {pages} pages, into {out}")
    return out


@pytest.mark.slow
def test_the_site_builds_with_warnings_as_errors(site: Path, registry: Registry) -> None:
    assert (site / "index.html").is_file() and (site / "search" / "search_index.json").is_file()
    assert (site / "rules" / "R006" / "index.html").is_file()
    assert (site / "parameters" / "P-AXIS-00178" / "index.html").is_file()
    assert (site / "commands" / "lint" / "index.html").is_file()
    assert sum(1 for _ in (site / "parameters").glob("P-*/index.html")) == len(registry.specs)
    home = (site / "index.html").read_text(encoding="utf-8")
    assert "fonts.googleapis.com" not in home  # nothing is fetched from the network


def _browser_missing() -> str | None:
    if importlib.util.find_spec("playwright") is None:
        return "playwright is not installed (pip install -e '.[docs]')"
    if not CHROMIUM.is_file():
        return f"no Chromium at {CHROMIUM} (apt-get install chromium)"
    return None


@pytest.fixture(scope="module")
def served(site: Path) -> Iterator[str]:
    """The built site on a local port, served from a thread."""
    handler = functools.partial(_QuietHandler, directory=str(site))
    server = http.server.ThreadingHTTPServer(("127.0.0.1", 0), handler)
    thread = threading.Thread(target=server.serve_forever, daemon=True)
    thread.start()
    try:
        yield f"http://127.0.0.1:{server.server_address[1]}/"
    finally:
        server.shutdown()
        server.server_close()


class _QuietHandler(http.server.SimpleHTTPRequestHandler):
    def log_message(self, format: str, *args: object) -> None:  # the base class names it `format`
        pass


def _search(page: object, base: str, text: str) -> list[str]:
    """Type ``text`` into Material's search box and return the result links' addresses."""
    from playwright.sync_api import Page

    assert isinstance(page, Page)
    page.goto(base)
    box = page.locator("input.md-search__input")  # in the header, on a wide screen
    box.click()
    box.fill(text)
    page.wait_for_selector("li.md-search-result__item a", timeout=60_000)
    return [str(a.get_attribute("href")) for a in page.locator("li.md-search-result__item a").all()]


@pytest.mark.slow
def test_a_browser_finds_things_in_the_site(served: str, tmp_path: Path) -> None:
    reason = _browser_missing()
    if reason:
        pytest.skip(reason)
    from playwright.sync_api import sync_playwright

    with sync_playwright() as p:
        browser = p.chromium.launch(executable_path=str(CHROMIUM), args=["--no-sandbox"])
        try:
            page = browser.new_page(viewport={"width": 1280, "height": 900})
            errors: list[str] = []
            page.on("pageerror", lambda exc: errors.append(str(exc)))
            links = _search(page, served, "swe_pos")
            assert any("parameters/P-AXIS-00178/" in link for link in links), links
            found = tmp_path / "search-swe_pos.png"
            page.screenshot(path=str(found))
            links = _search(page, served, "R006")
            assert any("rules/R006/" in link for link in links), links

            page.goto(served)
            home = tmp_path / "home.png"
            page.screenshot(path=str(home), full_page=True)
            assert "zero" in page.title()

            page.goto(served + "rules/R006/")
            example = page.locator("pre", has_text="getriebe[0].dynamik.a_emergency 5000").first
            example.wait_for(state="visible", timeout=10_000)
            assert page.locator(".hll", has_text="a_emergency 5000").count() >= 1  # the reported line, marked
            assert page.get_by_text("fail.lis:4:33: R006").first.is_visible()
            rule = tmp_path / "rule-R006.png"
            page.screenshot(path=str(rule), full_page=True)
            assert not errors, errors
            print(f"\nscreenshots: {home} {rule} {found}")
            keep = os.environ.get("ZERO_DOCS_SCREENSHOTS")  # a folder to keep them in, for a review
            if keep:
                Path(keep).mkdir(parents=True, exist_ok=True)
                for shot in (home, rule, found):
                    shutil.copy(shot, Path(keep) / shot.name)
        finally:
            browser.close()


# ------------------------------------------------------- issue 41: pages an engineer acts on


def test_rule_and_parameter_pages_link_both_ways() -> None:
    """The M, X, N and U rules' pages name the parameters their text names, linked; those parameters'
    pages list them under "Checked by" (the `swe_pos` page listed neither M001 nor X001)."""
    m005 = generated()["rules/M005.md"]()
    assert "| Parameters | [P-AXIS-00705](../parameters/P-AXIS-00705.md) `kenngr.swe_check` |" in m005
    assert "`kenngr.swe_check` ([P-AXIS-00705](../parameters/P-AXIS-00705.md))" in m005  # linked in the text too
    assert "[M005](../rules/M005.md)" in generated()["parameters/P-AXIS-00705.md"]()
    swe_pos = generated()["parameters/P-AXIS-00178.md"]()
    assert "[M001](../rules/M001.md)" in swe_pos and "[X001](../rules/X001.md)" in swe_pos
    assert "[S009]" not in swe_pos  # an example that merely shows the key is no check of it


# The rules that read no particular parameter (docs.GENERIC_RULES says why for each): listed here one by
# one, so that a new rule that declares nothing fails below until it declares what it reads or is added.
READS_NO_PARTICULAR_PARAMETER = {
    "S001", "S002", "S003", "S004", "S005", "S006", "S007", "S008", "S009", "S010", "S011", "S012", "S013",
    "S014", "S015", "S016", "S017",
    "R001", "R002", "R003", "R004", "R005", "R006", "R007", "R008", "R009", "R010", "R011", "R012", "R013",
    "U001", "Z001", "Z002", "F001", "N001", "N002", "N007", "N008", "N010",
}


def test_every_rule_declares_the_parameters_it_reads(registry: Registry) -> None:
    """Every M, X, N, U and K rule declares what its check reads (``Rule.reads``), each an ID or key the
    catalogue knows; only the rules listed above declare nothing, and each of those says why on its page."""
    undeclared = {code for code, r in RULES.items() if not r.reads}
    assert undeclared == READS_NO_PARTICULAR_PARAMETER
    assert set(docs.GENERIC_RULES) == READS_NO_PARTICULAR_PARAMETER
    assert docs.unknown_reads(registry) == []
    for code in RULES:
        if code[0] in "MXNUK" and code not in READS_NO_PARTICULAR_PARAMETER:
            assert docs.named_params(code, registry), code
    assert "| Parameters | none in particular: it reads the list's text" in generated()["rules/S001.md"]()


def test_a_declared_parameter_the_catalogue_does_not_know_is_found(registry: Registry,
                                                                     monkeypatch: pytest.MonkeyPatch) -> None:
    from zero.records import replace

    monkeypatch.setitem(RULES, "M005", replace(RULES["M005"], reads=("P-AXIS-99999", "kenngr.no_such_key")))
    assert docs.unknown_reads(registry) == [("M005", "P-AXIS-99999"), ("M005", "kenngr.no_such_key")]
    monkeypatch.setitem(RULES, "M005", replace(RULES["M005"], reads=("kenngr.swe_check",)))
    assert docs.unknown_reads(registry) == [] and docs.named_params("M005", registry) == ["P-AXIS-00705"]


def test_each_finding_is_on_a_parameter_its_rule_declares(registry: Registry) -> None:
    """The findings of the fixture machines, programs and rule fixtures, each reported on a parameter
    (``param_id``), are on one the rule declares it reads: the declaration is what the check does."""
    from zero.engine.lint import LintOptions, lint_data, lint_program

    failing, _ = docs._machine_results(ROOT, registry)
    found = [d for r in failing for d in r.diagnostics]
    for folder in sorted((ROOT / "fixtures" / "rules").iterdir()):
        for path in sorted(p for p in folder.iterdir() if p.is_file()):
            found += lint_data(path.read_bytes(), path.name, registry,
                               LintOptions(extend_select=(folder.name,))).diagnostics
    machine = docs._machine(ROOT / "fixtures" / "machine" / "listen" / "hochlauf.lis", registry)
    for program in ("bad.nc", "good.nc"):
        path = ROOT / "fixtures" / "programs" / program
        found += lint_program(path.read_bytes(), registry, program, machine=machine).diagnostics
    checked = [d for d in found if d.param_id and d.code not in READS_NO_PARTICULAR_PARAMETER]
    assert {d.code[0] for d in checked} >= set("MXNUK")
    wrong = {(d.code, d.param_id) for d in checked if d.param_id not in docs.named_params(d.code, registry)}
    assert not wrong


def test_declared_parameters_link_rule_and_parameter_pages() -> None:
    """M002 names no parameter ID in its text (it was linked to none); X001's parameter page lists it."""
    m002 = generated()["rules/M002.md"]()
    assert "[P-ZERO-00001](../parameters/P-ZERO-00001.md) `g53_verfuegbar`" in m002
    assert "[M002](../rules/M002.md)" in generated()["parameters/P-ZERO-00001.md"]()
    swe_check = generated()["parameters/P-AXIS-00705.md"]()
    assert "[M005](../rules/M005.md)" in swe_check and "[N006](../rules/N006.md)" in swe_check
    assert "[N009](../rules/N009.md)" in generated()["parameters/P-STUP-00018.md"]()
    assert "[X015](../rules/X015.md)" in generated()["parameters/P-RTCF-00002.md"]()


def test_the_rule_index_shows_code_not_backticks() -> None:
    index = generated()["rules/index.md"]()
    assert "\\`" not in index  # the literal backticks of `#`, `Ende`, `swe_check 0`
    assert "| Entries after the `Ende` line |" in index


def test_sources_are_links() -> None:
    page = generated()["rules/K093.md"]()
    assert "Source: <https://infosys.beckhoff.com/content/1031/tf5200_diagnosis/263914891.html>" in page
    assert "## Evidence" in generated()["rules/R004.md"]() and "<https://infosys.beckhoff.com/" in \
        generated()["rules/R004.md"]()


def test_each_kernel_rule_says_specifically_why_it_matters(registry: Registry) -> None:
    """From its documented correction: what the kernel does to which parameter at start-up."""
    from zero.rules.startup import CHECKS

    def why(code: str) -> str:
        page = generated()[f"rules/{code}.md"]()
        return page.split("## Why it matters on the machine", 1)[1].split("\n## ", 1)[0].strip()

    k093 = why("K093")
    assert "`getriebe[].gear_fact_denom`" in k093 and "to `1`" in k093 and "P-ERR-110580" in k093
    texts = {err.code: why(err.code) for err in CHECKS}
    assert len(set(texts.values())) == len(texts)  # one sentence each, no generic one
    for err in CHECKS:
        assert err.kernel_error in texts[err.code]
        if err.correction == "default":
            assert "its default" in texts[err.code]
        if err.correction == "abort":
            assert "aborts the start-up" in texts[err.code]


def test_example_output_wraps_instead_of_running_past_the_column() -> None:
    page = generated()["rules/K093.md"]()
    assert "```{ .text .zero-output }\nfail.lis:3:47: K093 error" in page
    css = (ROOT / "docs" / "assets" / "zero.css").read_text(encoding="utf-8")
    assert ".zero-output pre > code { white-space: pre-wrap;" in css


def test_parameter_pages_say_where_the_vendor_documents_them_and_german_terms(registry: Registry) -> None:
    swe_pos = generated()["parameters/P-AXIS-00178.md"]()
    assert "## Vendor documentation" in swe_pos
    assert "<https://infosys.beckhoff.com/content/1033/tf5200_axis_parameter/117162635.html>" in swe_pos
    assert "start-up error P-ERR-110110: <https://infosys.beckhoff.com/" in swe_pos
    assert "Search terms (German): Softwareendschalter, Endschalter" in swe_pos
    versch = generated()["parameters/P-ZERO-00003.md"]()
    assert "Nullpunktverschiebung" in versch
    assert docs.german_terms(registry.specs["P-AXIS-00152"])[:1] == ["Referenzpunkt"]  # getriebe[].pos_refpkt


def test_search_is_configured_for_english_and_german() -> None:
    text = (ROOT / "mkdocs.yml").read_text(encoding="utf-8")
    assert "lang: [en, de]" in text and "assets/filter.js" in text


@pytest.mark.slow
def test_the_built_site_finds_german_words_and_filters_tables(site: Path, served: str, tmp_path: Path) -> None:
    import json

    index = json.loads((site / "search" / "search_index.json").read_text(encoding="utf-8"))
    assert index["config"]["lang"] == ["en", "de"]
    reason = _browser_missing()
    if reason:
        pytest.skip(reason)
    from playwright.sync_api import sync_playwright

    with sync_playwright() as p:
        browser = p.chromium.launch(executable_path=str(CHROMIUM), args=[
            "--headless", "--no-sandbox", "--disable-gpu", "--disable-background-networking",
            "--disable-component-update", "--no-first-run"])
        try:
            page = browser.new_page(viewport={"width": 1366, "height": 900})
            errors: list[str] = []
            page.on("pageerror", lambda exc: errors.append(str(exc)))
            links = _search(page, served, "Endschalter")
            assert any("parameters/P-AXIS-00178/" in link or "parameters/P-AXIS-00177/" in link
                       for link in links), links
            links = _search(page, served, "Nullpunktverschiebung")
            assert any("parameters/P-ZERO-00003/" in link for link in links), links
            page.screenshot(path=str(tmp_path / "search-nullpunktverschiebung.png"))
            if CATALOGUE.is_file():  # a word only the catalogue's German names give, none of zero's glossary
                links = _search(page, served, "Festanschlag")
                named = {pid for pid, name in docs.german_names(CATALOGUE).items() if "Festanschlag" in name}
                assert links and all(link.split("/parameters/")[1].split("/")[0] in named for link in links), links
            links = _search(page, served, "Endschalter")
            page.screenshot(path=str(tmp_path / "search-endschalter.png"))

            page.goto(served + "parameters/AXIS/")
            box = page.locator("input.zero-filter").first
            total = page.locator("table tbody tr").count()
            box.fill("swe_pos")
            shown = page.locator("table tbody tr:visible")
            assert 0 < shown.count() < total and "P-AXIS-00178" in " ".join(shown.all_inner_texts())
            lines = page.eval_on_selector_all("table tbody tr:visible td:first-child a", """as => as.map(a => {
                const r = document.createRange(); r.selectNodeContents(a); return r.getClientRects().length; })""")
            assert lines and set(lines) == {1}  # an ID on one line
            page.screenshot(path=str(tmp_path / "params-filtered.png"))

            page.goto(served + "rules/K093/")
            out = page.locator(".zero-output pre").first
            assert out.evaluate("e => e.scrollWidth <= e.clientWidth + 1")  # not cut at the column edge
            assert page.locator("a[href='../../parameters/P-AXIS-00512/']").count() >= 1
            page.screenshot(path=str(tmp_path / "rule-K093.png"), full_page=True)
            assert not errors, errors
            keep = os.environ.get("ZERO_DOCS_SCREENSHOTS")
            if keep:
                Path(keep).mkdir(parents=True, exist_ok=True)
                for shot in ("params-filtered.png", "rule-K093.png", "search-endschalter.png",
                             "search-nullpunktverschiebung.png"):
                    shutil.copy(tmp_path / shot, Path(keep) / shot)
        finally:
            browser.close()


def _pages_with(monkeypatch: pytest.MonkeyPatch, catalogue: Path) -> dict[str, Callable[[], str]]:
    monkeypatch.setenv("ZERO_PARAM_DESC", str(catalogue))
    pages: dict[str, Callable[[], str]] = generator().pages()
    return pages


def test_the_catalogue_given_at_build_time_gives_german_names(corpus: Path, monkeypatch: pytest.MonkeyPatch,
                                                               registry: Registry) -> None:
    """Built with ``ZERO_PARAM_DESC``, each parameter page carries the German name the catalogue gives it, and
    the glossary's words inside its compounds (Softwareendschalterüberwachung: Endschalter); a parameter zero
    describes nowhere has the catalogue's English short description as its meaning."""
    pages = _pages_with(monkeypatch, CATALOGUE)
    swe_check = pages["parameters/P-AXIS-00705.md"]()
    assert "German name (from the CncParaDesc.xml this site was built with): Softwareendschalterüberwachung" \
        in swe_check
    assert re.search(r"Search terms \(German\): .*\bEndschalter\b", swe_check)
    assert "Festanschlag" in pages["parameters/P-AXIS-00330.md"]()
    assert "| meaning | Measurement with movement to a fixed stop (the short description in the CncParaDesc.xml " \
        "this site was built with) |" in pages["parameters/P-AXIS-00330.md"]()

    def undescribed(made: dict[str, Callable[[], str]]) -> int:
        return sum("| meaning | (no description" in made[docs.param_page_path(pid)]() for pid in registry.specs)

    assert undescribed(pages) < len(registry.specs) // 4 < undescribed(generated())  # 97 % said none without it
    assert "`CncParaDesc.xml`, read at build time through `ZERO_PARAM_DESC`" in pages["parameters/index.md"]()


def test_without_a_catalogue_no_vendor_text_reaches_the_pages(corpus: Path) -> None:
    """The site built without a catalogue (the one zero publishes) holds zero's glossary words only: none of
    the catalogue's German names of more than one word is on any parameter page."""
    names = docs.german_names(CATALOGUE)
    assert names["P-AXIS-00178"] == "Positiver Softwareendschalter"
    if os.environ.get("ZERO_PARAM_DESC"):
        pytest.skip("ZERO_PARAM_DESC is set: the pages are built with a catalogue")
    long_names = {pid: name for pid, name in names.items() if len(name.split()) > 1}
    for pid, name in long_names.items():
        page = generated()[docs.param_page_path(pid)]()
        assert docs.md_text(name) not in page, pid
    assert "German name" not in generated()["parameters/P-AXIS-00178.md"]()
    assert "Softwareendschalter, Endschalter" in generated()["parameters/P-AXIS-00178.md"]()  # the glossary's
    assert "zero does not ship" in generated()["parameters/index.md"]()


def test_a_bad_catalogue_at_build_time_is_a_located_error(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    from zero.errors import ZeroError

    bad = tmp_path / "CncParaDesc.xml"
    bad.write_text("<Parameters><Parameter>", encoding="utf-8")
    with pytest.raises(ZeroError, match="cannot read parameter description"):
        _pages_with(monkeypatch, bad)
    bad.write_text("<other/>", encoding="utf-8")
    with pytest.raises(ZeroError, match="not a CncParaDesc file"):
        _pages_with(monkeypatch, bad)
