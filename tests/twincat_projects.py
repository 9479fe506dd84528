"""TwinCAT projects written at run time for the tests (never committed): a 50 MB project."""

from __future__ import annotations

from pathlib import Path

from conftest import FIXTURES

PROJECT = FIXTURES / "twincat" / "project" / "Maschine.tsproj"


def big_project(target: Path, size: int = 52 * 1024 * 1024) -> int:
    """A project of ``size`` bytes: the fixture's CNC part between PLC and I/O configuration (written
    at run time, never committed). Returns how many lines were put before the CNC part."""
    data = PROJECT.read_text()
    head, rest = data.split("\t\t<Cnc>", 1)
    unit = ('\t\t\t<Device Id="{0}" DevType="111"><Name>Term {0} (EL1008)</Name><Vars VarGrpType="1"><Name>Inputs'
            '</Name><Var><Name>Input {0}</Name><Comment><![CDATA[<Data Name="Startup"> & not a list]]></Comment>'
            '<Type>BIT</Type></Var></Vars><!-- <Data Name="x" Offset="12"> --></Device>\n')
    count = size // 2 // len(unit.format(10**6))
    io = "\t\t<Io>\n" + "".join(unit.format(i) for i in range(count)) + "\t\t</Io>\n"
    with open(target, "w", encoding="utf-8") as f:
        f.write(head + io + "\t\t<Cnc>" + rest.replace("\t</Project>", io.replace("<Io>", "<Io2>").replace(
            "</Io>", "</Io2>") + "\t</Project>"))
    return io.count("\n")
