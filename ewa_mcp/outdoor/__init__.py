"""The outdoor world: street graphs of four city cores on real coordinates, points of interest,
rendered street views, walking directions and the street environment the agent walks in."""
