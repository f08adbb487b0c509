"""Joint tests: the eleven Box2D joints against box2d-reference.md."""
