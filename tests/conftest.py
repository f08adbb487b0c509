"""Suite-wide setup: headless pyglet (EGL) and the silent audio driver.

Set before anything imports pyglet, so render and audio tests run on machines
with no display and no sound device.
"""

import os

os.environ.setdefault("PYGLET_HEADLESS", "1")
os.environ.setdefault("PYGLET_AUDIO", "silent")
os.environ.setdefault("KGE_HEADLESS", "1")
