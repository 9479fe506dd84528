"""The XML forms of a list: the kernel's XML lists and update files, and TwinCAT's exports.

``safe`` reads XML with a hardened parser and the exact place of every tag; ``lists`` turns an
XML list into the list text every rule reads (and back); ``twincat`` finds the lists a TwinCAT
export holds in its CDATA sections (and puts one back).
"""
