"""Reading lists: bytes in, a :class:`~zero.lists.model.Document` out, never an exception.

``model`` (keys, entries, the document), ``encoding`` (the encodings a list may have,
decoded and written back byte for byte), ``tokenizer`` (the line scanner).
"""
