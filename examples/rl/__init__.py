"""Reinforcement-learning and scale-out examples on kge scenes (docs/rl.md)."""
