"""Per-episode shop state in SQLite: carts, wishlists and orders.

Every row carries the episode id, so concurrent episodes never see each other's state and
resetting one episode is a single DELETE per table. Money is kept in integer cents; the
catalogue's dollar prices are converted once, here.
"""

from __future__ import annotations

import sqlite3
import threading
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from . import catalog

MAX_QUANTITY = 99
FIRST_ORDER_NUMBER = 1001
# How an order reaches the customer: picked up at the store (the default), or delivered from the
# store to the episode's kitchen (the kitchen creates the groceries when it sees the order).
FULFILMENTS = ("pickup", "delivery")

SCHEMA = """
-- line_id and item_id are numbered per episode (1, 2, ... as the episode adds them, never reused in
-- it), so no page shows how many lines other episodes made and every episode sees the same numbers.
CREATE TABLE IF NOT EXISTS cart_lines (
    episode TEXT NOT NULL, line_id INTEGER NOT NULL,
    product_id TEXT NOT NULL, size TEXT NOT NULL, store_id TEXT NOT NULL,
    quantity INTEGER NOT NULL CHECK (quantity > 0),
    PRIMARY KEY (episode, line_id),
    UNIQUE (episode, product_id, size, store_id)
);
CREATE TABLE IF NOT EXISTS wishlist_items (
    episode TEXT NOT NULL, item_id INTEGER NOT NULL,
    product_id TEXT NOT NULL, size TEXT NOT NULL DEFAULT '',
    PRIMARY KEY (episode, item_id),
    UNIQUE (episode, product_id, size)
);
CREATE TABLE IF NOT EXISTS episode_numbers (
    episode TEXT NOT NULL, kind TEXT NOT NULL, last INTEGER NOT NULL,
    PRIMARY KEY (episode, kind)
);
CREATE TABLE IF NOT EXISTS orders (
    episode TEXT NOT NULL, order_id TEXT NOT NULL, number INTEGER NOT NULL, store_id TEXT NOT NULL,
    total_cents INTEGER NOT NULL, fulfilment TEXT NOT NULL DEFAULT 'pickup',
    PRIMARY KEY (episode, order_id)
);
CREATE TABLE IF NOT EXISTS order_items (
    episode TEXT NOT NULL, order_id TEXT NOT NULL, line INTEGER NOT NULL,
    product_id TEXT NOT NULL, size TEXT NOT NULL, quantity INTEGER NOT NULL,
    unit_price_cents INTEGER NOT NULL, kitchen_type TEXT,
    PRIMARY KEY (episode, order_id, line)
);
"""


class ShopError(Exception):
    """A refused shop action; ``status`` is the HTTP status to answer with."""

    def __init__(self, message: str, status: int = 400):
        super().__init__(message)
        self.message = message
        self.status = status


def cents(dollars: float) -> int:
    return round(dollars * 100)


def dollars(amount_cents: int) -> float:
    return round(amount_cents / 100, 2)


@dataclass
class CartLine:
    line_id: int
    product: catalog.Product
    size: str
    store: catalog.Store
    quantity: int
    unit_price_cents: int

    @property
    def subtotal_cents(self) -> int:
        return self.unit_price_cents * self.quantity


@dataclass
class WishlistItem:
    item_id: int
    product: catalog.Product
    size: str  # "" means any size


@dataclass
class OrderItem:
    product: catalog.Product
    size: str
    quantity: int
    unit_price_cents: int
    kitchen_type: str | None

    @property
    def subtotal_cents(self) -> int:
        return self.unit_price_cents * self.quantity


@dataclass
class Order:
    order_id: str
    number: int
    store: catalog.Store
    total_cents: int
    items: list[OrderItem]
    fulfilment: str = "pickup"

    def event_payload(self) -> dict[str, Any]:
        """The order exactly as graders and the kitchen read it from the order_placed event."""
        return {
            "order_id": self.order_id,
            "store_id": self.store.id,
            "fulfilment": self.fulfilment,
            "items": [{"product_id": i.product.id, "size": i.size, "quantity": i.quantity,
                       "kitchen_type": i.kitchen_type, "unit_price": dollars(i.unit_price_cents)}
                      for i in self.items],
            "total": dollars(self.total_cents),
        }


@dataclass
class QuoteLine:
    """One product and size of the cart priced at one store: ``unit_price_cents`` is None where the store
    does not sell it; ``left`` is that store's stock for this episode."""

    product: catalog.Product
    size: str
    quantity: int
    unit_price_cents: int | None
    left: int


@dataclass
class StoreQuote:
    """What the cart would cost when picked up at one store, and what stops it."""

    store: catalog.Store
    total_cents: int
    problems: list[str]
    lines: list[QuoteLine] = field(default_factory=list)


class ShopState:
    def __init__(self, path: Path | None = None):
        target = str(path) if path is not None else ":memory:"
        self._db = sqlite3.connect(target, check_same_thread=False, isolation_level=None)
        self._db.row_factory = sqlite3.Row
        self._lock = threading.Lock()  # one connection, used from the server thread and test threads
        with self._lock:
            for table, key in (("cart_lines", "line_id"), ("wishlist_items", "item_id")):
                columns = [row[1] for row in self._db.execute(f"PRAGMA table_info({table})")]
                if columns and columns[0] == key:
                    # A database kept from before per-episode numbering (--site-data-dir): its carts and
                    # wishlists numbered lines across episodes; they are per-episode scratch, so they go.
                    self._db.execute(f"DROP TABLE {table}")
            self._db.executescript(SCHEMA)

    def close(self) -> None:
        with self._lock:
            self._db.close()

    def _query(self, sql: str, params: tuple[Any, ...] = ()) -> list[sqlite3.Row]:
        with self._lock:
            return self._db.execute(sql, params).fetchall()

    def _next_number(self, episode: str, kind: str) -> int:
        """The episode's next cart-line or wishlist number (the caller holds the lock)."""
        self._db.execute("INSERT INTO episode_numbers (episode, kind, last) VALUES (?, ?, 1) "
                         "ON CONFLICT (episode, kind) DO UPDATE SET last = last + 1", (episode, kind))
        row = self._db.execute("SELECT last FROM episode_numbers WHERE episode=? AND kind=?", (episode, kind))
        return int(row.fetchone()["last"])

    # ------------------------------------------------------------ validation
    @staticmethod
    def _product(product_id: str) -> catalog.Product:
        try:
            return catalog.get_product(product_id)
        except catalog.CatalogError as exc:
            raise ShopError(str(exc), 404) from None

    @classmethod
    def _product_size(cls, product_id: str, size: str) -> catalog.Product:
        product = cls._product(product_id)
        try:
            product.size(size)
        except catalog.CatalogError as exc:
            raise ShopError(str(exc), 400) from None
        return product

    @staticmethod
    def _store(store_id: str) -> catalog.Store:
        try:
            return catalog.get_store(store_id)
        except catalog.CatalogError as exc:
            raise ShopError(str(exc), 400) from None

    @staticmethod
    def _check_quantity(quantity: int) -> None:
        if not 1 <= quantity <= MAX_QUANTITY:
            raise ShopError(f"Quantity must be between 1 and {MAX_QUANTITY}; you asked for {quantity}.")

    def available(self, episode: str, product_id: str, size: str, store_id: str) -> int:
        """Shelf stock at the store minus what this episode has already ordered there."""
        offer = catalog.get_product(product_id).offer(size, store_id)
        if offer is None:
            return 0
        rows = self._query(
            "SELECT COALESCE(SUM(i.quantity), 0) AS n FROM order_items i JOIN orders o "
            "ON o.episode = i.episode AND o.order_id = i.order_id "
            "WHERE i.episode = ? AND o.store_id = ? AND i.product_id = ? AND i.size = ?",
            (episode, store_id, product_id, size))
        return max(0, offer.stock - rows[0]["n"])

    # ------------------------------------------------------------ cart
    def add_to_cart(self, episode: str, product_id: str, size: str, store_id: str, quantity: int) -> CartLine:
        product = self._product_size(product_id, size)
        store = self._store(store_id)
        self._check_quantity(quantity)
        if product.offer(size, store_id) is None:
            names = ", ".join(catalog.get_store(s).name for s in product.store_ids)
            raise ShopError(f"{store.name} does not sell {product.name}. Choose one of: {names}.", 409)
        existing = self._query("SELECT quantity FROM cart_lines WHERE episode=? AND product_id=? AND size=? "
                               "AND store_id=?", (episode, product_id, size, store_id))
        new_quantity = quantity + (existing[0]["quantity"] if existing else 0)
        self._check_quantity(new_quantity)
        left = self.available(episode, product_id, size, store_id)
        if new_quantity > left:
            raise ShopError(f"{store.name} has only {left} of {product.name} ({size}) in stock; "
                            f"lower the quantity or choose another store.", 409)
        with self._lock:
            # Looked up again under the lock: another request of the episode may have added the line meanwhile.
            if self._db.execute("SELECT 1 FROM cart_lines WHERE episode=? AND product_id=? AND size=? AND store_id=?",
                                (episode, product_id, size, store_id)).fetchall():
                self._db.execute("UPDATE cart_lines SET quantity=? WHERE episode=? AND product_id=? AND size=? "
                                 "AND store_id=?", (new_quantity, episode, product_id, size, store_id))
            else:
                self._db.execute(
                    "INSERT INTO cart_lines (episode, line_id, product_id, size, store_id, quantity) "
                    "VALUES (?, ?, ?, ?, ?, ?)",
                    (episode, self._next_number(episode, "cart"), product_id, size, store_id, new_quantity))
        return next(line for line in self.cart(episode)
                    if (line.product.id, line.size, line.store.id) == (product_id, size, store_id))

    def cart_line(self, episode: str, line_id: int) -> CartLine:
        for line in self.cart(episode):
            if line.line_id == line_id:
                return line
        raise ShopError(f"Your cart has no line {line_id}; open the cart and use its buttons.", 404)

    def update_cart_line(self, episode: str, line_id: int, quantity: int) -> CartLine:
        line = self.cart_line(episode, line_id)
        self._check_quantity(quantity)
        left = self.available(episode, line.product.id, line.size, line.store.id)
        if quantity > left:
            raise ShopError(f"{line.store.name} has only {left} of {line.product.name} ({line.size}) in stock; "
                            f"lower the quantity or choose another store.", 409)
        with self._lock:
            self._db.execute("UPDATE cart_lines SET quantity=? WHERE episode=? AND line_id=?",
                             (quantity, episode, line_id))
        line.quantity = quantity
        return line

    def remove_cart_line(self, episode: str, line_id: int) -> CartLine:
        line = self.cart_line(episode, line_id)
        with self._lock:
            self._db.execute("DELETE FROM cart_lines WHERE episode=? AND line_id=?", (episode, line_id))
        return line

    def cart(self, episode: str) -> list[CartLine]:
        lines = []
        for row in self._query("SELECT * FROM cart_lines WHERE episode=? ORDER BY line_id", (episode,)):
            product = catalog.get_product(row["product_id"])
            offer = product.offer(row["size"], row["store_id"])
            lines.append(CartLine(row["line_id"], product, row["size"], catalog.get_store(row["store_id"]),
                                  row["quantity"], cents(offer.price) if offer else 0))
        return lines

    def cart_count(self, episode: str) -> int:
        return self._query("SELECT COALESCE(SUM(quantity), 0) AS n FROM cart_lines WHERE episode=?",
                           (episode,))[0]["n"]

    # ------------------------------------------------------------ checkout
    def quote(self, episode: str, store_id: str) -> StoreQuote:
        """Price the whole cart at one pickup store and list every line it cannot fill."""
        store = self._store(store_id)
        needed: dict[tuple[str, str], int] = {}
        lines = self.cart(episode)
        for line in lines:
            key = (line.product.id, line.size)
            needed[key] = needed.get(key, 0) + line.quantity
        total, problems, priced = 0, [], []
        for (product_id, size), quantity in needed.items():
            product = catalog.get_product(product_id)
            offer = product.offer(size, store_id)
            if offer is None:
                problems.append(f"{store.name} does not sell {product.name} ({size}).")
                priced.append(QuoteLine(product, size, quantity, None, 0))
                continue
            left = self.available(episode, product_id, size, store_id)
            if quantity > left:
                problems.append(f"{store.name} has {left} of {product.name} ({size}) in stock; your cart has "
                                f"{quantity}.")
            total += cents(offer.price) * quantity
            priced.append(QuoteLine(product, size, quantity, cents(offer.price), left))
        return StoreQuote(store, total, problems, priced)

    def place_order(self, episode: str, store_id: str, fulfilment: str = "pickup") -> Order:
        if fulfilment not in FULFILMENTS:
            raise ShopError(f"Unknown fulfilment {fulfilment[:40]!r}; choose pickup or delivery.")
        lines = self.cart(episode)
        if not lines:
            raise ShopError("Your cart is empty; add a product to the cart before checking out.", 409)
        quote = self.quote(episode, store_id)
        if quote.problems:
            raise ShopError(" ".join(quote.problems) + " Choose another pickup store or change your cart.", 409)
        items: list[OrderItem] = []
        merged: dict[tuple[str, str], OrderItem] = {}
        for line in lines:  # the same product and size from two cart lines becomes one order item
            offer = line.product.offer(line.size, store_id)
            assert offer is not None  # quote() checked it
            key = (line.product.id, line.size)
            if key in merged:
                merged[key].quantity += line.quantity
                continue
            merged[key] = OrderItem(line.product, line.size, line.quantity, cents(offer.price),
                                    line.product.kitchen_type)
            items.append(merged[key])
        with self._lock:
            number = self._db.execute("SELECT COALESCE(MAX(number), ?) + 1 AS n FROM orders WHERE episode=?",
                                      (FIRST_ORDER_NUMBER - 1, episode)).fetchone()["n"]
            order = Order(f"EWA-{number}", number, quote.store, quote.total_cents, items, fulfilment)
            self._db.execute("BEGIN")
            try:
                self._db.execute("INSERT INTO orders VALUES (?, ?, ?, ?, ?, ?)",
                                 (episode, order.order_id, number, store_id, order.total_cents, fulfilment))
                self._db.executemany(
                    "INSERT INTO order_items VALUES (?, ?, ?, ?, ?, ?, ?, ?)",
                    [(episode, order.order_id, n, i.product.id, i.size, i.quantity, i.unit_price_cents,
                      i.kitchen_type) for n, i in enumerate(items)])
                self._db.execute("DELETE FROM cart_lines WHERE episode=?", (episode,))
                self._db.execute("COMMIT")
            except BaseException:
                self._db.execute("ROLLBACK")
                raise
        return order

    # ------------------------------------------------------------ orders
    def orders(self, episode: str) -> list[Order]:
        rows = self._query("SELECT * FROM orders WHERE episode=? ORDER BY number DESC", (episode,))
        return [self._order_from_row(episode, row) for row in rows]

    def order(self, episode: str, order_id: str) -> Order:
        rows = self._query("SELECT * FROM orders WHERE episode=? AND order_id=?", (episode, order_id))
        if not rows:
            raise ShopError(f"No order {order_id!r} in your order history; see the Orders page for your orders.",
                            404)
        return self._order_from_row(episode, rows[0])

    def _order_from_row(self, episode: str, row: sqlite3.Row) -> Order:
        items = [OrderItem(catalog.get_product(i["product_id"]), i["size"], i["quantity"], i["unit_price_cents"],
                           i["kitchen_type"])
                 for i in self._query("SELECT * FROM order_items WHERE episode=? AND order_id=? ORDER BY line",
                                      (episode, row["order_id"]))]
        return Order(row["order_id"], row["number"], catalog.get_store(row["store_id"]), row["total_cents"], items,
                     row["fulfilment"])

    # ------------------------------------------------------------ wishlist
    def add_to_wishlist(self, episode: str, product_id: str, size: str) -> WishlistItem:
        product = self._product_size(product_id, size) if size else self._product(product_id)
        with self._lock:
            if not self._db.execute("SELECT 1 FROM wishlist_items WHERE episode=? AND product_id=? AND size=?",
                                    (episode, product_id, size)).fetchall():
                self._db.execute("INSERT INTO wishlist_items (episode, item_id, product_id, size) VALUES (?, ?, ?, ?)",
                                 (episode, self._next_number(episode, "wishlist"), product_id, size))
        return next(i for i in self.wishlist(episode) if i.product.id == product.id and i.size == size)

    def remove_from_wishlist(self, episode: str, item_id: int) -> WishlistItem:
        for item in self.wishlist(episode):
            if item.item_id == item_id:
                with self._lock:
                    self._db.execute("DELETE FROM wishlist_items WHERE episode=? AND item_id=?", (episode, item_id))
                return item
        raise ShopError(f"Your wishlist has no item {item_id}; open the wishlist and use its buttons.", 404)

    def wishlist(self, episode: str) -> list[WishlistItem]:
        return [WishlistItem(r["item_id"], catalog.get_product(r["product_id"]), r["size"])
                for r in self._query("SELECT * FROM wishlist_items WHERE episode=? ORDER BY item_id", (episode,))]

    # ------------------------------------------------------------ episodes
    def reset_episode(self, episode: str) -> None:
        with self._lock:
            for table in ("cart_lines", "wishlist_items", "orders", "order_items", "episode_numbers"):
                self._db.execute(f"DELETE FROM {table} WHERE episode=?", (episode,))  # table names are constants

    def snapshot(self, episode: str) -> dict[str, Any]:
        """The episode's shop state as JSON (for final_state.json)."""
        return {
            "cart": [{"product_id": l.product.id, "size": l.size, "store_id": l.store.id, "quantity": l.quantity}
                     for l in self.cart(episode)],
            "wishlist": [{"product_id": i.product.id, "size": i.size or None} for i in self.wishlist(episode)],
            "orders": [o.event_payload() for o in reversed(self.orders(episode))],
        }
