"""Character movement: collide-and-slide against the world in numpy (see kge.systems.character)."""
