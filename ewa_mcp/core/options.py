"""Per-episode options a client may pass to start_episode.

The kernel's own options are below; each environment declares the options it reads (``EnvironmentSpec.options``,
a pydantic model in its world package, each option named with its world's prefix), and ``episode_options()``
assembles start_episode's parameter from the kernel's and every registered environment's, so that the kernel
names no world's options and a plugin world adds its own as a built-in one does.
"""

from __future__ import annotations

from typing import Any, Literal

from pydantic import BaseModel, ConfigDict, Field, create_model

from . import registry


class EpisodeOptions(BaseModel):
    model_config = ConfigDict(extra="forbid")

    observation: Literal["text", "vision", "both"] = Field(
        "text", description="text: scene graph / accessibility tree; vision: images; both: all"
    )
    seed: int | None = Field(None, description="override the task's scene seed")
    structured: Literal["full", "compact"] | None = Field(
        None, description="structured content of observations: full (the observation's data; the default) or "
                          "compact (status and step counts only; the text carries the observation)")


def episode_options() -> type[EpisodeOptions]:
    """start_episode's options: the kernel's, then each registered environment's in the order its tools are
    listed, as one model named EpisodeOptions (unknown options are refused, naming the known ones)."""
    fields: dict[str, Any] = {}
    owner: dict[str, str] = {name: "the kernel" for name in EpisodeOptions.model_fields}
    for env in registry.ordered_environments():
        if env.options is None:
            continue
        model = registry.load_object(env.options)
        if not (isinstance(model, type) and issubclass(model, BaseModel)):
            raise registry.RegistryError(f"{env.options!r}, the options of {env.name!r}, is not a pydantic model; "
                                         "name a BaseModel class")
        for name, info in model.model_fields.items():
            if name in owner:
                raise registry.RegistryError(f"the option {name!r} of {env.name!r} is already declared by "
                                             f"{owner[name]}; name it with the environment's prefix")
            owner[name] = repr(env.name)
            fields[name] = (info.annotation, info)
    if not fields:
        return EpisodeOptions
    assembled: type[EpisodeOptions] = create_model("EpisodeOptions", __base__=EpisodeOptions,
                                                   __module__=__name__, **fields)
    return assembled
