# SPDX-License-Identifier: BSD-3-Clause
"""The one order both type models export in: each type after the types it contains."""


def contained_first(roots, dependencies):
    """roots and everything dependencies(item) reaches from them, each item
    after the items it reaches, without recursion (types nest deeply)."""
    ordered = []
    seen = set()
    for root in roots:
        if root in seen:
            continue
        seen.add(root)
        stack = [(root, iter(dependencies(root)))]
        while stack:
            item, pending = stack[-1]
            dependency = next(pending, None)
            if dependency is None:
                stack.pop()
                ordered.append(item)
            elif dependency not in seen:
                seen.add(dependency)
                stack.append((dependency, iter(dependencies(dependency))))
    return ordered
