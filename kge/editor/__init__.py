"""``kge edit``: the scene editor, a kge App built on kge.ui (docs/editor.md).

:class:`EditorModel` is the scene being edited with its undo history (headless, what the
window shows and what tests drive); :func:`editor_app` builds the window around it.
"""

from kge.editor.model import EditorModel, EditorOnly

__all__ = ["EditorModel", "EditorOnly"]
