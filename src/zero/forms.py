"""What a file is, by its name (a parameter list, an NC program, a list's structured form) and, for
XML, by its content (a kernel XML list, a TwinCAT export holding lists, or no list at all).

The one place that knows the suffixes. ``zero lint`` picks the reader by it, a directory
walk picks up lists and programs by it (the default ``include``), ``zero convert`` takes the
format from it, the language server decides how to analyse a document by it, and a report
written with ``-o`` never replaces a file of these kinds.
"""

from __future__ import annotations

import os

from zero.patterns import compiled

LIST, PROGRAM, STRUCTURED = "list", "program", "structured"
LIST_SUFFIXES = (".lis", ".lst")
PROGRAM_SUFFIXES = (".nc", ".mpf", ".spf")  # NC programs (zero.nc)
PROGRAM_SUFFIX = PROGRAM_SUFFIXES[0]  # the suffix of a subprogram called by a name without one (`L sub` → sub.nc)
STRUCTURED_SUFFIXES = {".yaml": "yaml", ".yml": "yaml", ".toml": "toml", ".json": "json"}
COMMENTED_FORMS = ("yaml", "toml")  # the structured forms that hold comments (and so noqa directives)
# XML: a list by its root element, never by the suffix alone (a TwinCAT project holds many XML files).
XML_SUFFIX = ".xml"
# TwinCAT projects and their independent project files (zero.markup.tsproj): lists in `<Data>` CDATA.
INDEPENDENT_SUFFIX = ".xti"
PROJECT_SUFFIXES = (".tsproj", INDEPENDENT_SUFFIX)
# What a directory walk picks up: lists, NC programs, and XML files that hold lists (by content:
# zero.engine.discovery.holds_lists skips every other XML file in silence), and TwinCAT projects.
WALKED_SUFFIXES = (*LIST_SUFFIXES, *PROGRAM_SUFFIXES, XML_SUFFIX, *PROJECT_SUFFIXES)
DEFAULT_INCLUDE = tuple(f"*{s}" for s in WALKED_SUFFIXES)
CONFIG_NAMES = ("zero.toml", ".zero.toml", "pyproject.toml")  # nearest wins; in this order within a folder
# A report (`zero lint -o FILE`) never replaces one of these: lists, programs, list forms (JSON: reports too),
# configuration.
NOT_A_REPORT = (*LIST_SUFFIXES, *PROGRAM_SUFFIXES, *(s for s, f in STRUCTURED_SUFFIXES.items() if f != "json"))
# The suffix `zero convert` writes for each format, in the order --to lists them.
EXTENSION = {"lis": LIST_SUFFIXES[0], "yaml": ".yaml", "toml": ".toml", "json": ".json", "xml": XML_SUFFIX}

XML_LIST, TWINCAT = "xml", "twincat"
# The root element of each list kind in the kernel's XML lists.
XML_ROOTS: dict[str, str] = {
    "StartUp": "STUP", "AX_MDS": "AXIS", "Default_AX_MDS": "AXIS", "SDA_MDS": "CHAN",
    "Default_SDA_MDS": "CHAN", "ZeroOffset": "ZERO", "ToolData": "TOOL", "ClampPosOffset": "CLMP",
    "ManualMode": "MANU", "ExtVar": "EXTV", "AX_COMP": "COMP", "VolComp": "VOLC",
    "RTConfiguration": "RTCF",
}
TWINCAT_ROOT = "TreeItem"  # a TwinCAT tree item export (System Manager, Automation Interface)
PROJECT_ROOTS = ("TcSmProject", "TcSmItem")  # a TwinCAT project (`.tsproj`), an independent project file (`.xti`)
# The elements of a TwinCAT export that hold a list in CDATA, and the list kind each holds.
EMBEDDED: dict[str, str] = {"AchsMds": "AXIS", "SdaMds": "CHAN", "NullpD": "ZERO", "WerkzD": "TOOL",
                            "PzvD": "CLMP", "VeD": "EXTV", "Startup": "STUP"}
_BOM = b"\xef\xbb\xbf"
_SPACE = b" \t\r\n\f\v"
_NAME_START = rb"[A-Za-z_]"  # compiled at their first use (re keeps them): XML only
_NAME_END = rb"[\s/>]"


def _suffix(name: str | os.PathLike[str]) -> str:
    """``os.path.splitext(name)[1].lower()``, in a few calls in C (a run asks a dozen questions of each file's
    name; a fleet's 6,300 files outgrew a memo): the text from the last dot of the last part, where a
    character other than a dot comes before it in that part (``.lis`` alone is a name without a suffix)."""
    text = os.fspath(name)
    cut = text.rfind(os.sep) if os.altsep is None else max(text.rfind(os.sep), text.rfind(os.altsep))
    dot = text.rfind(".")
    return text[dot:].lower() if dot > cut and text[cut + 1:dot].strip(".") else ""


def form_of(name: str | os.PathLike[str]) -> str:
    """A list, an NC program or a structured form; a list unless the suffix says otherwise."""
    suffix = _suffix(name)
    if suffix in PROGRAM_SUFFIXES:
        return PROGRAM
    if suffix in STRUCTURED_SUFFIXES:
        return STRUCTURED
    return LIST


def is_list(name: str | os.PathLike[str]) -> bool:
    """A parameter list by its name (not an NC program, not a YAML/TOML/JSON form)."""
    return form_of(name) == LIST


def is_program(name: str | os.PathLike[str]) -> bool:
    return _suffix(name) in PROGRAM_SUFFIXES


# A list's kind by fragments of its file name (`nullp_d1.lis`, `achsmds1.lis`), first match: only
# to break a tie when its keys fit several kinds equally (zero.catalog.registry.Registry.detect_kind).
KIND_HINTS = (
    ("nullp", "ZERO"), ("achskw", "COMP"), ("achs", "AXIS"), ("mds", "AXIS"),
    ("sda", "CHAN"), ("werkz", "TOOL"), ("tool", "TOOL"), ("hand", "MANU"),
    ("hochlauf", "STUP"), ("startup", "STUP"), ("rtconf", "RTCF"), ("ext_var", "EXTV"),
    ("pzv", "CLMP"), ("zero", "ZERO"),
)


def kind_hint(name: str | os.PathLike[str]) -> str | None:
    """The list kind a file's name suggests (its four letters, ``ZERO``), else ``None``."""
    base = os.path.basename(os.fspath(name)).lower()
    return next((kind for fragment, kind in KIND_HINTS if fragment in base), None)


def structured_format(name: str | os.PathLike[str]) -> str | None:
    """``"yaml"``, ``"toml"`` or ``"json"`` for a structured form by its name, else ``None``."""
    return STRUCTURED_SUFFIXES.get(_suffix(name))


def is_xml_name(name: str | os.PathLike[str]) -> bool:
    """An XML file by its name (a list, a TwinCAT export or anything else: the content tells)."""
    return _suffix(name) == XML_SUFFIX


def is_independent_file(name: str | os.PathLike[str]) -> bool:
    """A TwinCAT independent project file (``Achse_X.xti``) by its name, as a project names it."""
    return _suffix(name) == INDEPENDENT_SUFFIX


def walked_names() -> str:
    """What a directory walk looks for, in words: ``*.lis, *.lst, … and *.xti``."""
    return ", ".join(DEFAULT_INCLUDE[:-1]) + " and " + DEFAULT_INCLUDE[-1]


def format_of(name: str | os.PathLike[str]) -> str | None:
    """The format a file name implies for `zero convert` (``None`` when the suffix says nothing)."""
    suffix = _suffix(name)
    if suffix == XML_SUFFIX or suffix in PROJECT_SUFFIXES:
        return "xml"
    return "lis" if suffix in LIST_SUFFIXES else STRUCTURED_SUFFIXES.get(suffix)


def is_xml(data: bytes) -> bool:
    """Does the content start like XML (a list never starts with `<`)?"""
    head = data[3:64] if data.startswith(_BOM) else data[:64]
    return head.lstrip()[:1] == b"<"


def root_of(data: bytes) -> str | None:
    """The name of the root element, from the first 64 KiB, without parsing; ``None`` when there is none.

    A scan, not a regular expression: declarations, processing instructions and comments are
    skipped each in one ``find`` (a pattern with a lazy comment inside a repetition backtracked
    exponentially over a run of comments: 28 of them took 86 s)."""
    head = data[3:65536] if data.startswith(_BOM) else data[:65536]
    i, n = 0, len(head)
    while True:
        while i < n and head[i] in _SPACE:
            i += 1
        if head.startswith(b"<?", i):
            end = head.find(b"?>", i + 2)
            if end < 0 or b">" in head[i + 2:end]:  # `<?…>` with a `>` before its `?>`: not a declaration
                return None
            i = end + 2
        elif head.startswith(b"<!--", i):
            end = head.find(b"-->", i + 4)
            if end < 0:
                return None
            i = end + 3
        elif head.startswith(b"<", i) and compiled(_NAME_START).match(head, i + 1):
            stop = compiled(_NAME_END).search(head, i + 2)
            return head[i + 1: stop.start() if stop else n].decode("ascii", "replace")
        else:
            return None


def xml_form(data: bytes) -> str | None:
    """``"xml"`` for a kernel XML list, ``"twincat"`` for a TwinCAT export (its root element), else
    ``None``: XML of any other kind, or no XML."""
    if not is_xml(data):
        return None
    root = root_of(data)
    if root in XML_ROOTS:
        return XML_LIST
    return TWINCAT if root == TWINCAT_ROOT or root in PROJECT_ROOTS else None


def is_project(name: str | os.PathLike[str]) -> bool:
    """A TwinCAT project or independent project file by its name (``X.tsproj``, ``Achse_X.xti``)."""
    return _suffix(split_part(name)[0]) in PROJECT_SUFFIXES


def is_update(name: str | os.PathLike[str]) -> bool:
    """An update or revert file by its place (the kernel's ``Update`` folder) or its name
    (``achsmds1-Update.xml``, ``achsmds1-Revert.xml``): inside, the two look like any XML list."""
    path = os.fspath(name)
    stem = os.path.splitext(os.path.basename(path))[0].lower()
    return os.path.basename(os.path.dirname(path)).lower() == "update" or \
        stem.endswith(("-update", "-revert", "_update", "_revert"))


def split_part(path: str | os.PathLike[str]) -> tuple[str, str | None]:
    """``channel_1.xml#NullpD`` (a list inside a TwinCAT export, as a machine names it) or
    ``X.tsproj#Kanal_1/SdaMds`` (a list inside a TwinCAT project) → the file and the element; any
    other path → itself and ``None``."""
    text = os.fspath(path)
    file, sep, element = text.rpartition("#")
    if sep and element and _suffix(file) in PROJECT_SUFFIXES:
        return file, element
    return (file, element) if sep and element in EMBEDDED else (text, None)


KERNEL_ROOT = "CncKernelRootDir"  # the kernel's own folder, as its XML start-up lists name it


def controller_absolute(text: str) -> bool:
    """An absolute path on the controller, as a start-up list or `roots` writes it: ``/…``, ``C:\\…``,
    ``C:/…``, ``\\\\server\\…``, or below the kernel's root folder (``CncKernelRootDir/config/…``)."""
    return text.startswith(("/", "\\")) or (len(text) >= 3 and text[0].isalpha() and text[1] == ":"
                                            and text[2] in "/\\") or kernel_rooted(text)


def kernel_rooted(text: str) -> bool:
    return text.replace("\\", "/").split("/", 1)[0].lower() == KERNEL_ROOT.lower()
