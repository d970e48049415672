"""Groceries from the shop arriving in the kitchen.

A shop order placed with "Deliver to my kitchen" (a web event ``order_placed`` with ``fulfilment: delivery``)
materialises each item's ``kitchen_type`` on the emptiest CounterTop through AI2-THOR's
``CreateObjectAtLocation``, over any backend; a pickup order brings nothing and says so. Each item is recorded
in ``KitchenSession.deliveries`` (and the final state) with what arrived where, or why not.
``KitchenSession.receive_deliveries`` reads the new events and calls ``deliver_order`` for each order.
"""

from __future__ import annotations

from typing import Any, Protocol

from .vocabulary import DELIVERABLE_TYPES, canonical_type


class KitchenSession(Protocol):
    """What a delivery needs of the kitchen session (session.py's ``KitchenSession`` provides it): declared
    here so that the session imports this module and never the other way round."""

    controller: Any  # a controller with AI2-THOR's step(action=..., ...) (backends.py)
    objects: dict[str, dict[str, Any]]
    deliveries: list[dict[str, Any]]

    def _refresh(self, metadata: dict[str, Any]) -> None: ...
    def _readable(self, message: str) -> str: ...
    def _number(self, object_id: str) -> int: ...
    def handle(self, object_id: str | None) -> str: ...
    def parent_of(self, obj: dict[str, Any]) -> str | None: ...


def deliver_order(session: KitchenSession, order: dict[str, Any]) -> list[str]:
    """What one shop order brings to the kitchen: a line per item that arrived or could not."""
    items = [i for i in order.get("items") or [] if isinstance(i, dict) and i.get("kitchen_type")]
    if items and order.get("fulfilment") != "delivery":
        # Only an order placed for delivery comes to the kitchen; say so once for a pickup order.
        kinds = ", ".join(sorted({str(i["kitchen_type"]) for i in items}))
        return [f"Order {order.get('order_id')} ({kinds}) is for pickup at the store, so nothing "
                "arrives in this kitchen; to get groceries here, order them with 'Deliver to my "
                "kitchen' at checkout."]
    notes: list[str] = []
    for item in items:
        notes.extend(deliver_item(session, order, item))
    return notes


def deliver_item(session: KitchenSession, order: dict[str, Any], item: dict[str, Any]) -> list[str]:
    kind = canonical_type(str(item["kitchen_type"])) or str(item["kitchen_type"])
    try:
        quantity = max(1, min(10, int(item.get("quantity", 1))))
    except (TypeError, ValueError):
        quantity = 1
    record: dict[str, Any] = {
        "order_id": order.get("order_id"), "store_id": order.get("store_id"),
        "product_id": item.get("product_id"), "kitchen_type": kind, "quantity": quantity,
        "objectIds": [], "handles": [], "receptacle": None, "status": "delivered",
    }
    session.deliveries.append(record)
    if kind not in DELIVERABLE_TYPES:
        record["status"] = "not_a_kitchen_object"
        return [f"The order's {kind} is not something this kitchen can hold; nothing arrived for it."]
    notes = []
    for _ in range(quantity):
        counter = delivery_counter(session)
        if counter is None:
            record["status"] = "failed"
            record["message"] = "this kitchen has no CounterTop"
            break
        box = counter["axisAlignedBoundingBox"]
        top = box["center"]["y"] + box["size"]["y"] / 2
        before = set(session.objects)
        event = session.controller.step(action="CreateObjectAtLocation", objectType=kind, forceAction=True,
                                        position={"x": box["center"]["x"], "y": top + 0.05, "z": box["center"]["z"]},
                                        rotation={"x": 0.0, "y": 0.0, "z": 0.0})
        if not event.metadata["lastActionSuccess"]:
            record["status"] = "failed"
            record["message"] = session._readable(str(event.metadata["errorMessage"]))
            notes.append(f"A delivery of {kind} could not be placed: {record['message']}")
            break
        session._refresh(event.metadata)
        for object_id in session.objects:
            if object_id not in before:
                record["objectIds"].append(object_id)
                record["handles"].append(session.handle(object_id))
                record["receptacle"] = session.parent_of(session.objects[object_id])
                notes.append(f"A delivery arrived: {session.handle(object_id)} on "
                             f"{session.handle(record['receptacle'])}.")
    return notes


def delivery_counter(session: KitchenSession) -> dict[str, Any] | None:
    counters = [o for o in session.objects.values() if o["objectType"] == "CounterTop"]
    if not counters:
        return None
    # The emptiest counter, the lowest handle first: deterministic and where there is room.
    return min(counters, key=lambda o: (len(o.get("receptacleObjectIds") or []), session._number(o["objectId"])))
