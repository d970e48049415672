"""Geolocation domain: locations, standpoint graphs, rendered views, the environment, task and wiki generators."""
