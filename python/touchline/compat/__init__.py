"""Compatibility layers for code written against other football environments.

* `touchline.compat.gfootball`: Google Research Football's `create_environment` and old gym API.
"""
