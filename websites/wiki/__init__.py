"""The embedded encyclopedia: articles written for this project, served with FTS5 search.

``ewa_mcp.websites.wiki.store`` is the Python API the task generator uses; ``app.create_app``
is the Starlette site.
"""
