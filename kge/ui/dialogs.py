"""Dialogs: closing one with a result, and ready-made message boxes.

:func:`message_box` spawns a modal :class:`~kge.components.ui.Dialog` with a text and
a row of buttons; clicking one (or Escape, result -1) emits
:class:`~kge.ui.events.DialogClosed` and removes the dialog. :func:`confirm` is the
usual two-button case. The keyboard focus starts on the default button.

>>> from kge.world import World
>>> from kge.components.ui import Button, Dialog
>>> w = World()
>>> d = confirm(w, "Quit the game?", ok="Quit")
>>> sorted(b.text for _, (b,) in w.query(Button)), w.get(d, Dialog).modal
(['Cancel', 'Quit'], True)
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING

from kge.components.ui import Button, Dialog, DialogButton, Label, UINode
from kge.errors import ValidationError
from kge.ui.events import DialogClosed
from kge.world import World

if TYPE_CHECKING:
    from kge.ui.interact import Frame


def close_dialog(f: Frame, dialog: int, result: int, text: str) -> None:
    """Close ``dialog`` with ``result``: emit DialogClosed, then despawn or hide it."""
    d = f.world.try_get(dialog, Dialog)
    if d is None:
        return
    f.emit(DialogClosed(dialog, result, text))
    if f.state.focused is not None and f.layout.dialog.get(f.state.focused) == dialog:
        f.focus(None)
    if d.keep:
        f.world.get(dialog, UINode).visible = False
    else:  # despawned once its on_dialog_closed hook has run (kge.systems.ui)
        f.state.doomed.extend(f.layout.subtree(dialog))


def message_box(world: World, text: str, buttons: Sequence[str] = ("OK",), *, title: str = "",
                default: int = 0, width: float = 360, cancel: bool = True) -> int:  # fmt: skip
    """Spawn a modal dialog showing ``text`` with one button per entry of ``buttons``
    (their results are their indices); returns the dialog's entity. Read the answer
    from :class:`~kge.ui.events.DialogClosed` (or an ``on_dialog_closed`` hook on the
    dialog's entity)."""
    if not buttons:
        raise ValidationError("message_box: buttons must name at least one button")
    if not 0 <= default < len(buttons):
        raise ValidationError(
            f"message_box: default {default} is not an index of its {len(buttons)} buttons"
        )
    dialog = world.spawn(
        UINode(width=width, layout="column", padding=16, spacing=14, align="stretch"),
        Dialog(title, modal=True, cancel=cancel),
    )
    world.spawn(UINode(parent=dialog), Label(text, wrap=True, align="left"))
    row = world.spawn(UINode(parent=dialog, layout="row", spacing=10, justify="end",
                             height="auto"))  # fmt: skip
    first = None
    for i, name in enumerate(buttons):
        b = world.spawn(UINode(parent=row, min_width=90, height=38), Button(name), DialogButton(i))
        if i == default:
            first = b
    from kge.ui.state import UIState

    state = world.try_resource(UIState)
    if state is not None and first is not None:
        state.touch(state.focused, first)
        state.focused = first
    return dialog


def confirm(world: World, text: str, *, ok: str = "OK", cancel: str = "Cancel",
            title: str = "") -> int:  # fmt: skip
    """A yes/no dialog: results 1 (``ok``) and 0 (``cancel``; Escape gives -1)."""
    return message_box(world, text, (cancel, ok), title=title, default=1)
