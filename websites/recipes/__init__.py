"""The recipes site: search and filter hand-written recipes, follow one step by step."""
