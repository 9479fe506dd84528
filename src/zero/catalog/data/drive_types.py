"""The drive types of each parameter, drive_types.toml compiled.

Generated: do not edit."""

from __future__ import annotations

TYPE_CHECKING = False  # typing.TYPE_CHECKING without importing typing (zero.hints)
if TYPE_CHECKING:
    from typing import Any

DRIVE_TYPES: list[dict[str, Any]] = [
    {'param': 'P-AXIS-00106', 'types': [2], 'names': 'SERCOS (lr_hw[].mask_mess_1)', 'source': 'https://infosys.beckhoff.com/content/1033/tf5200_axis_parameter/117337611.html'},
    {'param': 'P-AXIS-00060', 'types': [2], 'names': 'SERCOS (kenngr.echtzeit_bit_nr)', 'source': 'https://infosys.beckhoff.com/content/1031/tf5200_axis_parameter/117336075.html'},
    {'key': 'antr.sercos.', 'types': [2], 'names': 'SERCOS (the antr.sercos.* parameters)', 'source': 'https://infosys.beckhoff.com/content/1033/tf5200_axis_parameter/117965323.html'},
    {'param': 'P-AXIS-00294', 'types': [5], 'names': 'Lightbus', 'source': 'https://infosys.beckhoff.com/content/1031/tf5200_axis_parameter/117257867.html'},
    {'param': 'P-AXIS-00388', 'types': [2], 'names': 'SERCOS ("this parameter is currently supported only for SERCOS")', 'source': 'https://infosys.beckhoff.com/content/1031/tf5200_axis_parameter/117920395.html'},
    {'param': 'P-AXIS-00539', 'types': [2, 3], 'names': 'SERCOS, Profidrive (remarks: a value other than 0 for other drive types is error 110614)', 'source': 'https://infosys.beckhoff.com/content/1033/tf5200_axis_parameter/117333003.html'},
    {'param': 'P-AXIS-00355', 'types': [2, 5, 8], 'names': 'SERCOS, Lightbus, CANopen', 'source': 'https://infosys.beckhoff.com/content/1033/tf5200_axis_parameter/117260939.html'},
    {'param': 'P-AXIS-00584', 'types': [2, 8], 'names': 'SERCOS, CANopen', 'source': 'https://infosys.beckhoff.com/content/1033/tf5200_axis_parameter/478018443.html'},
    {'param': 'P-AXIS-00346', 'types': [2], 'names': 'SERCOS, KUKA (KUKA has no P-AXIS-00020 number)', 'source': 'https://infosys.beckhoff.com/content/1033/tf5200_axis_parameter/117292939.html'},
    {'param': 'P-AXIS-00709', 'types': [4, 2, 3, 8, 6], 'names': 'Simulation, SERCOS, Profidrive, CANopen, Terminal', 'source': 'https://infosys.beckhoff.com/content/1031/tf5200_axis_parameter/117947403.html'},
    {'param': 'P-AXIS-00426', 'types': [2], 'names': "SERCOS (remarks: 'at the moment supported for drive type SERCOS only')", 'source': 'https://infosys.beckhoff.com/content/1033/tf5200_axis_parameter/117303691.html'},
    {'param': 'P-AXIS-00425', 'types': [2], 'names': "SERCOS (remarks: 'supported for SERCOS drive types only')", 'source': 'https://infosys.beckhoff.com/content/1033/tf5200_axis_parameter/117302155.html'},
    {'param': 'P-AXIS-00405', 'types': [2, 8], 'names': 'SERCOS, CANopen (remarks: coarsening the encoder resolution is currently possible with SERCOS and CANopen drives only)', 'source': 'https://infosys.beckhoff.com/content/1031/tf5200_axis_parameter/117930507.html'},
    {'param': 'P-AXIS-00328', 'types': [2, 3, 8], 'names': 'SERCOS, Profidrive, CANopen', 'source': 'https://infosys.beckhoff.com/content/1033/tf5200_axis_parameter/117797003.html'},
]
