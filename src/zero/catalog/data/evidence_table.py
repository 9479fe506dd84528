"""The claims of evidence.toml (what the controller does, and the source), compiled; DRIVES from drive_types.toml.

CLAIMS: a line per row, a claim's rows together, its fields separated by tabs: name, consequence, severity, says, source, releases, kinds, kernel_error (kinds separated by commas).
RULES: a line per rule: its code, a tab, the name of its claim.

Generated: do not edit."""

from __future__ import annotations

TYPE_CHECKING = False  # typing.TYPE_CHECKING without importing typing (zero.hints)
if TYPE_CHECKING:
    from typing import Any

DRIVES: list[dict[str, Any]] = [{'key': 'lr_hw[].mask_mess_1', 'types': [2], 'source': 'https://infosys.beckhoff.com/content/1033/tf5200_axis_parameter/117337611.html'}, {'key': 'kenngr.echtzeit_bit_nr', 'types': [2], 'source': 'https://infosys.beckhoff.com/content/1031/tf5200_axis_parameter/117336075.html'}, {'key': 'antr.sercos.', 'types': [2], 'source': 'https://infosys.beckhoff.com/content/1033/tf5200_axis_parameter/117965323.html'}, {'key': 'kenngr.homing_overflow_evaluation', 'types': [5], 'source': 'https://infosys.beckhoff.com/content/1031/tf5200_axis_parameter/117257867.html'}, {'key': 'antr.cnc_homing_encoder', 'types': [2], 'source': 'https://infosys.beckhoff.com/content/1031/tf5200_axis_parameter/117920395.html'}, {'key': 'kenngr.measure.input_edge_banding', 'types': [2, 3], 'source': 'https://infosys.beckhoff.com/content/1033/tf5200_axis_parameter/117333003.html'}, {'key': 'antr.encoder_bit_range', 'types': [2, 5, 8], 'source': 'https://infosys.beckhoff.com/content/1033/tf5200_axis_parameter/117260939.html'}, {'key': 'kenngr.write_reference_position_to_drive', 'types': [2, 8], 'source': 'https://infosys.beckhoff.com/content/1033/tf5200_axis_parameter/478018443.html'}, {'key': 'kenngr.homing.torq_homing_dir', 'types': [2], 'source': 'https://infosys.beckhoff.com/content/1033/tf5200_axis_parameter/117292939.html'}, {'key': 'antr.add_ready_for_operation.bit_nr', 'types': [4, 2, 3, 8, 6], 'source': 'https://infosys.beckhoff.com/content/1031/tf5200_axis_parameter/117947403.html'}, {'key': 'antr.reference_check.element_name', 'types': [2], 'source': 'https://infosys.beckhoff.com/content/1033/tf5200_axis_parameter/117303691.html'}, {'key': 'antr.reference_check.bit_nr', 'types': [2], 'source': 'https://infosys.beckhoff.com/content/1033/tf5200_axis_parameter/117302155.html'}, {'key': 'antr.encoder_coarsening_factor', 'types': [2, 8], 'source': 'https://infosys.beckhoff.com/content/1031/tf5200_axis_parameter/117930507.html'}, {'key': 'lr_param.distance_control_on', 'types': [2, 3, 8], 'source': 'https://infosys.beckhoff.com/content/1033/tf5200_axis_parameter/117797003.html'}]
CLAIMS: str = (
    "\n"
    'unknown-element\taborted\terror\tthe plausibility check of a zero-offset list reports an unknown or incorrectly written parameter or an invalid value (P-ERR-20407), and the kernel aborts the job\thttps://infosys.beckhoff.com/content/1033/tf5200_diagnosis/251542155.html\tTF5200 diagnosis documentation\tZERO\tP-ERR-20407\n'
    'unknown-element\tignored\terror\tthe kernel ignores an element of an axis parameter list it cannot interpret (P-ERR-1001119)\thttps://infosys.beckhoff.com/content/1033/tf5200_diagnosis/269215627.html\tTF5200 diagnosis documentation (kernel V3.1)\tAXIS\tP-ERR-1001119\n'
    'unknown-element\tundocumented\twarning\tthe vendor documents no reaction to an unknown element of this list kind (P-ERR-1001119 covers axis parameter lists only)\tnone: the diagnosis documentation covers unknown elements of axis parameter lists only (P-ERR-1001119)\tall\t\t\n'
    "vendor-writes\tvendor-writes\tinfo\tthe vendor's own lists or templates write it, which is evidence that the kernel of their release accepts it\tthe vendor's lists and templates (zero's tables name the file of each)\tthe release of the list or template named\t\t\n"
    "other-release\tundocumented\twarning\tzero's catalogue does not document it; whether the machine's kernel accepts it is not documented\tnone: zero's table of renames and removals names where each spelling was seen\tall\t\t\n"
    'number-format\taborted\terror\tthe plausibility check of a zero-offset list reports an unknown or incorrectly written parameter or an invalid value (P-ERR-20407), and the kernel aborts the job\thttps://infosys.beckhoff.com/content/1033/tf5200_diagnosis/251542155.html\tTF5200 diagnosis documentation\tZERO\tP-ERR-20407\n'
    'number-format\tzeroed\terror\tthe kernel goes on with the list and sets a value of an invalid number format to 0 (P-ERR-1001138)\thttps://infosys.beckhoff.com/content/1033/tf5200_diagnosis/269276555.html\tTF5200 diagnosis documentation (kernel V3.1)\tAXIS\tP-ERR-1001138\n'
    'number-format\tundocumented\twarning\twhat the controller does with a value of the wrong type in this list kind is not documented (P-ERR-1001138 covers axis parameter lists only)\tnone: the diagnosis documentation covers number formats of axis parameter lists only (P-ERR-1001138)\tall\t\t\n'
    'out-of-range\taborted\terror\tthe plausibility check of a zero-offset list reports an unknown or incorrectly written parameter or an invalid value (P-ERR-20407), and the kernel aborts the job\thttps://infosys.beckhoff.com/content/1033/tf5200_diagnosis/251542155.html\tTF5200 diagnosis documentation\tZERO\tP-ERR-20407\n'
    'out-of-range\tlimited\terror\tthe kernel goes on with the list and limits the value to the permissible minimum or maximum (P-ERR-1001138)\thttps://infosys.beckhoff.com/content/1033/tf5200_diagnosis/269276555.html\tTF5200 diagnosis documentation (kernel V3.1)\tAXIS\tP-ERR-1001138\n'
    'out-of-range\tundocumented\twarning\tthe vendor does not document that the controller checks this range in this list kind, nor what it would do (P-ERR-1001138 covers axis parameter lists only)\tnone: the diagnosis documentation covers value ranges of axis parameter lists only (P-ERR-1001138)\tall\t\t\n'
    'not-listed\taborted\terror\tthe plausibility check of a zero-offset list reports an unknown or incorrectly written parameter or an invalid value (P-ERR-20407), and the kernel aborts the job\thttps://infosys.beckhoff.com/content/1033/tf5200_diagnosis/251542155.html\tTF5200 diagnosis documentation\tZERO\tP-ERR-20407\n'
    "not-listed\tundocumented\twarning\tthe documentation lists the allowed values but does not say what the controller does with another one\tnone: P-ERR-1001138 speaks of a range's minimum and maximum, not of listed values\tall\t\t\n"
    "application-specific\tundocumented\tinfo\tthe documentation calls this range application-specific: a given controller's limit may differ (the vendor's own lists exceed some), and what it does beyond it is not documented\tthe parameter's documented range (`application-specific`), e.g. https://infosys.beckhoff.com/content/1033/tf5200_axis_parameter/117379083.html\tall\t\t\n"
    "drive-type\tnot-applicable\tinfo\tthe documentation gives the parameter for another drive type than the axis has (P-AXIS-00020): the kernel does not use it for this axis\tthe parameter's documented drive types, e.g. https://infosys.beckhoff.com/content/1033/tf5200_axis_parameter/117337611.html and https://infosys.beckhoff.com/content/1033/tf5200_axis_parameter/117965323.html\tTF5200 axis parameter documentation\tAXIS\t\n"
    "relation\tundocumented\twarning\tthe vendor documents no start-up check of this relation: what the controller does with the value is not documented\tnone: the relation is the catalogue's range; no diagnosis page reports it (where one does, its K rule says so instead)\tall\t\t\n"
    'unknown-reference\tundocumented\twarning\twhat the controller does with a reference to a parameter it does not have is not documented\tnone\tall\t\t\n'
    "catalogue-contradiction\tundocumented\twarning\tthe catalogue contradicts itself here, and what the controller does is not documented\tthe catalogue (CncParaDesc.xml): its default lies outside its own range\tthe catalogue's\t\t\n"
    "unit-unknown\tundocumented\tinfo\tthe catalogue gives no unit for the value, so whether it lies inside the range is not known\tthe catalogue (CncParaDesc.xml)\tthe catalogue's\t\t\n"
    "duplicate\tbehaviour\twarning\tthe later value is the one that stays\tthe list format: entries are read top to bottom (the vendor's SERCOS lists set kenngr.antr_typ twice)\tall\t\t\n"
    'annotation\tbehaviour\twarning\tnothing for the controller, which ignores comments\tthe list format\tall\t\t\n'
    'malformed-line\taborted\terror\tthe plausibility check of a zero-offset list reports an unknown or incorrectly written parameter or an invalid value (P-ERR-20407), and the kernel aborts the job\thttps://infosys.beckhoff.com/content/1033/tf5200_diagnosis/251542155.html\tTF5200 diagnosis documentation\tZERO\tP-ERR-20407\n'
    'malformed-line\tignored\terror\tthe kernel ignores an element of an axis parameter list it cannot interpret (P-ERR-1001119)\thttps://infosys.beckhoff.com/content/1033/tf5200_diagnosis/269215627.html\tTF5200 diagnosis documentation (kernel V3.1)\tAXIS\tP-ERR-1001119\n'
    'malformed-line\tundocumented\twarning\twhat the controller does with a line it cannot read in this list kind is not documented\tnone: P-ERR-1001119 covers axis parameter lists only\tall\t\t\n'
    'unreadable-entry\taborted\terror\tthe plausibility check of a zero-offset list reports an unknown or incorrectly written parameter or an invalid value (P-ERR-20407), and the kernel aborts the job\thttps://infosys.beckhoff.com/content/1033/tf5200_diagnosis/251542155.html\tTF5200 diagnosis documentation\tZERO\tP-ERR-20407\n'
    'unreadable-entry\tundocumented\twarning\twhat the controller does with such an entry is not documented\tnone\tall\t\t\n'
    'unknown-parameter-id\tundocumented\twarning\twhat the kernel does with an XML element of a parameter ID its catalogue does not have is not documented\tnone\tall\t\t\n'
    'text\tundocumented\twarning\twhat the controller does with these bytes is not documented\tnone\tall\t\t\n'
    'after-end\tbehaviour\twarning\tthe list ends at `Ende`\tthe list format (SPEC: a list ends with `Ende`)\tall\t\t\n'
    "style\tbehaviour\twarning\tnothing for the controller: the manual's form of a list\tthe vendor's list format\tall\t\t\n"
    "style-info\tbehaviour\tinfo\tnothing for the controller: the manual's form of a list, which the vendor's own lists do not keep\tthe vendor's list format and lists\tall\t\t\n"
    'unchecked\tunchecked\terror\tzero could not read the file, so nothing in it was checked\tzero: the file did not read\tall\t\t\n'
    'empty-soft-limits\tundocumented\twarning\tthe kernel documents an error for an empty travel range (P-ERR-110110, K042), not for inverted soft limits: what it does with these is not documented\thttps://infosys.beckhoff.com/content/1033/tf5200_diagnosis/262387339.html\tTF5200 diagnosis documentation\tAXIS\t\n'
    "behaviour\tbehaviour\twarning\tthe documented behaviour of the value, which may not be what was meant\tthe parameter's documentation (each rule names it)\tall\t\t\n"
    "information\tbehaviour\tinfo\tthe documented behaviour; often intended\tthe parameter's documentation\tall\t\t\n"
    'feed-constant\tbehaviour\tinfo\tthe TwinCAT CNC axis documentation puts wegaufz/wegaufn (P-AXIS-00234/00233) into the feed-constant formula as the gear ratio; the TF5200 documentation names gear_fact_num/denom (P-AXIS-00511/00512) for it\thttps://infosys.beckhoff.com/content/1033/tccncaxisparameter/15267153035.html and https://infosys.beckhoff.com/content/1033/tf5200_axis_parameter/131271307.html\tTwinCAT CNC (V3.01) and TF5200 axis parameter documentation\tAXIS\t\n'
    "restart\tbehaviour\twarning\tthe catalogue marks the parameter as taking effect only at a restart\tthe catalogue (CncParaDesc.xml restart flag)\tthe catalogue's\t\t\n"
    'update-axis-zero\trejected\terror\tthe kernel refuses to interpret an axis list for the logical axis number 0: the list is not updated (P-ERR-110597)\thttps://infosys.beckhoff.com/content/1033/tf5200_diagnosis/263988875.html\tTF5200 diagnosis documentation\t\tP-ERR-110597\n'
    'update-axis-unknown\trejected\terror\tthe kernel rejects an order to take over parameters for a logical axis number no axis has (P-ERR-1000099)\thttps://infosys.beckhoff.com/content/1033/tf5200_diagnosis/268837003.html\tTF5200 diagnosis documentation\t\tP-ERR-1000099\n'
    'duplicate-axis\trejected\terror\tthe kernel rejects the data transfer of the second axis with the same logical axis number (P-ERR-110064) or does not configure it (P-ERR-1001121)\thttps://infosys.beckhoff.com/content/1033/tf5200_diagnosis/262200203.html and https://infosys.beckhoff.com/content/1033/tf5200_diagnosis/269224331.html\tTF5200 diagnosis documentation\t\t\n'
    'missing-list\taborted\terror\twhere the system tries to open a list file it cannot find, it outputs error messages and aborts the start-up (P-STUP-00015)\thttps://infosys.beckhoff.com/content/1033/tf5200_startup_list/123509643.html\tTF5200 start-up list documentation\t\t\n'
    'channel-axis-without-list\trejected\terror\tat start-up the channel whose axis number no axis list has gets no axes (P-ERR-3210)\thttps://infosys.beckhoff.com/content/1033/tf5200_diagnosis/249505419.html\tTF5200 diagnosis documentation\t\t\n'
    'machine-undocumented\tundocumented\twarning\twhat the controller does is not documented\tnone\tall\t\t\n'
    'machine-information\tbehaviour\tinfo\tinformation about what zero checked\tzero\tall\t\t\n'
    "machine-data-rejected\trejected\terror\tthe controller rejects the block when the program runs\tthe vendor's #MACHINE DATA manual (shared/seeds, seed 003)\tall\t\t\n"
    'programmed-limits-crossed\trejected\terror\tthe value is not taken over and the controller resets (P-ERR-21649, P-ERR-21878)\thttps://infosys.beckhoff.com/content/1033/tf5200_diagnosis/ (P-ERR-21649, P-ERR-21878), as the N004 rule cites\tTF5200 diagnosis documentation\t\t\n'
)
RULES: str = (
    "\n"
    'S001\tmalformed-line\n'
    'S002\tunreadable-entry\n'
    'S003\tunreadable-entry\n'
    'S004\tmalformed-line\n'
    'S005\tstyle\n'
    'S006\tstyle\n'
    'S007\ttext\n'
    'S008\ttext\n'
    'S009\tafter-end\n'
    'S010\ttext\n'
    'S011\tstyle-info\n'
    'S012\tstyle-info\n'
    'S013\tunchecked\n'
    'S014\tunchecked\n'
    'S015\tunknown-parameter-id\n'
    'S016\tmachine-information\n'
    'S017\tunchecked\n'
    'R001\tunknown-element\n'
    'R002\tvendor-writes\n'
    'R003\tunknown-element\n'
    'R004\tnumber-format\n'
    'R005\tout-of-range\n'
    'R006\trelation\n'
    'R007\tduplicate\n'
    'R008\tannotation\n'
    'R009\tunknown-reference\n'
    'R010\tvendor-writes\n'
    'R011\tcatalogue-contradiction\n'
    'R012\tunit-unknown\n'
    'R013\tother-release\n'
    'M001\tempty-soft-limits\n'
    'M002\tbehaviour\n'
    'M003\tinformation\n'
    'M004\tbehaviour\n'
    'M005\tbehaviour\n'
    'M006\tbehaviour\n'
    'M007\tbehaviour\n'
    'M008\tmachine-undocumented\n'
    'M009\tfeed-constant\n'
    'U001\trestart\n'
    'U002\tupdate-axis-zero\n'
    'U003\tupdate-axis-unknown\n'
    'X001\tbehaviour\n'
    'X002\tmachine-undocumented\n'
    'X003\tmachine-undocumented\n'
    'X004\tduplicate-axis\n'
    'X005\tmissing-list\n'
    'X006\tbehaviour\n'
    'X007\tchannel-axis-without-list\n'
    'X008\tbehaviour\n'
    'X009\tmachine-undocumented\n'
    'X010\tmachine-undocumented\n'
    'X011\tmachine-undocumented\n'
    'X012\tmachine-information\n'
    'X013\tbehaviour\n'
    'X014\tmachine-undocumented\n'
    'N001\tmachine-data-rejected\n'
    'N002\tbehaviour\n'
    'N003\tbehaviour\n'
    'N004\tprogrammed-limits-crossed\n'
    'F001\tunchecked\n'
)
