package org.openworld.engine.core;

import java.util.ArrayList;
import java.util.Collections;
import java.util.Comparator;
import java.util.EnumSet;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.PriorityQueue;
import java.util.Set;
import java.util.stream.Collectors;

/**
 * Resolves the frame order of systems from their declarations (CONTRIBUTING.md, "Declared order"), never from the order they were added.
 *
 * <p>Edges, each "runs before":
 * <ul>
 *   <li>{@code after("x")}: x before the declaring system;</li>
 *   <li>data: a system that writes a type runs before every system that only reads it (a published type,
 *       {@code publishes()}, orders nothing);</li>
 *   <li>layers ({@link Layer}): a system {@link Layer#OVER_OPAQUE over the opaque picture} (the water, which sees
 *       through to it) or {@link Layer#TRANSPARENT transparent} after every system of an earlier layer that draws in
 *       one of its passes;</li>
 * </ul>
 * A {@link Layer#BACKGROUND background} (the sky) has no edge of its own: its update keeps its place in the frame
 * order, so an opaque system may read what it writes (the sun), while in each pass it draws after every opaque system
 * of that pass ({@link #drawOrder}), shaded only where they left the far plane.
 * Two systems that write the same type must be ordered by {@code after} (directly or through other
 * {@code after}s), or the declaration is ambiguous and resolution fails. A cycle fails and names its edges. Among
 * systems free to go in any order, the alphabetically first goes first, so the order is stable and printable.
 */
public final class SystemOrder {

    private final List<EngineSystem> ordered;
    private final Map<String, List<String>> reasons;

    private SystemOrder(List<EngineSystem> ordered, Map<String, List<String>> reasons) {
        this.ordered = List.copyOf(ordered);
        this.reasons = reasons;
    }

    /** Resolves the order or throws {@link SystemOrderException} saying what is wrong. */
    public static SystemOrder resolve(List<? extends EngineSystem> systems) {
        Map<String, EngineSystem> byName = new LinkedHashMap<>();
        for (EngineSystem system : systems) {
            if (byName.put(system.spec().name(), system) != null) {
                throw new SystemOrderException("two systems are named '" + system.spec().name() + "'");
            }
        }
        Graph graph = new Graph(byName.keySet());
        for (EngineSystem system : systems) {
            SystemSpec spec = system.spec();
            for (String before : spec.after()) {
                if (!byName.containsKey(before)) {
                    throw new SystemOrderException("system '" + spec.name() + "' runs after '" + before
                            + "', but no system of that name is added (added: " + String.join(", ", byName.keySet()) + ")");
                }
                graph.edge(before, spec.name(), spec.name() + " declares after(" + before + ")");
            }
        }
        requireOrderedWriters(systems, graph);
        for (EngineSystem blended : systems) {
            SystemSpec t = blended.spec();
            for (EngineSystem opaque : systems) {
                SystemSpec o = opaque.spec();
                Set<Pass> shared = EnumSet.noneOf(Pass.class);
                shared.addAll(t.passes());
                shared.retainAll(o.passes());
                if (shared.isEmpty()) {
                    continue;
                }
                if (t.layer().followsEarlierLayers() && o.layer().compareTo(t.layer()) < 0) {
                    graph.edge(o.name(), t.name(), t.name() + (t.layer() == Layer.TRANSPARENT
                            ? " is transparent, blended over what " : " is drawn over the opaque picture, which it "
                            + "reads: over what ") + o.name() + " draws in " + shared.iterator().next().label());
                }
            }
        }
        for (EngineSystem writer : systems) {
            for (Class<?> type : writer.spec().writes()) {
                for (EngineSystem reader : systems) {
                    SystemSpec r = reader.spec();
                    if (reader != writer && r.reads().contains(type) && !r.writes().contains(type)) {
                        graph.edge(writer.spec().name(), r.name(), r.name() + " reads " + type.getSimpleName()
                                + ", which " + writer.spec().name() + " writes");
                    }
                }
            }
        }
        List<String> names = graph.sort();
        return new SystemOrder(names.stream().map(byName::get).toList(), graph.reasons());
    }

    private static void requireOrderedWriters(List<? extends EngineSystem> systems, Graph explicit) {
        for (int i = 0; i < systems.size(); i++) {
            for (int j = i + 1; j < systems.size(); j++) {
                SystemSpec a = systems.get(i).spec();
                SystemSpec b = systems.get(j).spec();
                Set<Class<?>> both = new LinkedHashSet<>(a.writes());
                both.retainAll(b.writes());
                if (!both.isEmpty() && !explicit.reaches(a.name(), b.name()) && !explicit.reaches(b.name(), a.name())) {
                    throw new SystemOrderException("systems '" + a.name() + "' and '" + b.name() + "' both write "
                            + both.stream().map(Class::getSimpleName).collect(Collectors.joining(", "))
                            + ": declare which runs first with after(...)");
                }
            }
        }
    }

    /** The systems in frame order. */
    public List<EngineSystem> systems() {
        return ordered;
    }

    /**
     * The systems that draw in or prepare {@code pass}, in the order they draw: the frame order, except that the
     * backgrounds draw right after the last opaque system of the pass, so before whatever is drawn over the opaque
     * picture or blended over it (those follow every opaque system in the frame order).
     */
    public List<EngineSystem> drawOrder(Pass pass) {
        List<EngineSystem> draw = new ArrayList<>();
        List<EngineSystem> backgrounds = new ArrayList<>();
        int behindOpaque = 0;
        for (EngineSystem system : ordered) {
            SystemSpec spec = system.spec();
            if (!spec.passes().contains(pass) && !spec.prepared().contains(pass)) {
                continue;
            }
            if (spec.layer() == Layer.BACKGROUND) {
                backgrounds.add(system);
                continue;
            }
            draw.add(system);
            if (spec.passes().contains(pass) && spec.layer() == Layer.OPAQUE) {
                behindOpaque = draw.size();
            }
        }
        draw.addAll(behindOpaque, backgrounds);
        return draw;
    }

    /** The order as text, one system a line with what it declares and why it stands where it does. */
    public String describe() {
        StringBuilder s = new StringBuilder();
        int i = 1;
        for (EngineSystem system : ordered) {
            SystemSpec spec = system.spec();
            s.append(String.format("%2d. %-12s", i++, spec.name()));
            s.append(" draws ").append(spec.passes().isEmpty() ? "-"
                    : spec.passes().stream().map(Pass::label).collect(Collectors.joining(",")));
            if (!spec.prepared().isEmpty()) {
                s.append("; prepares ").append(spec.prepared().stream().map(Pass::label).collect(Collectors.joining(",")));
            }
            s.append("; writes ").append(simpleNames(spec.writes()));
            if (!spec.published().isEmpty()) {
                s.append("; publishes ").append(simpleNames(spec.published()));
            }
            s.append("; reads ").append(simpleNames(spec.reads()));
            s.append('\n');
            for (String reason : reasons.getOrDefault(spec.name(), List.of())) {
                s.append("      after: ").append(reason).append('\n');
            }
        }
        for (Pass pass : Pass.values()) {
            List<EngineSystem> draw = drawOrder(pass);
            if (!draw.isEmpty()) {
                s.append(String.format("Drawing in %s: ", pass.label())).append(draw.stream()
                        .map(d -> d.spec().name()).collect(Collectors.joining(", "))).append('\n');
            }
        }
        return s.toString();
    }

    private static String simpleNames(Set<Class<?>> types) {
        return types.isEmpty() ? "-" : types.stream().map(Class::getSimpleName).collect(Collectors.joining(","));
    }

    /** A directed graph over system names with a reason per edge. */
    private static final class Graph {
        private final Map<String, Map<String, String>> out = new LinkedHashMap<>();

        Graph(Set<String> nodes) {
            nodes.forEach(n -> out.put(n, new LinkedHashMap<>()));
        }

        void edge(String from, String to, String reason) {
            out.get(from).putIfAbsent(to, reason);
        }

        boolean reaches(String from, String to) {
            Set<String> seen = new HashSet<>();
            List<String> stack = new ArrayList<>(List.of(from));
            while (!stack.isEmpty()) {
                String n = stack.remove(stack.size() - 1);
                if (n.equals(to)) {
                    return true;
                }
                if (seen.add(n)) {
                    stack.addAll(out.get(n).keySet());
                }
            }
            return false;
        }

        /** Kahn's algorithm, alphabetical among the ready nodes. */
        List<String> sort() {
            Map<String, Integer> incoming = new LinkedHashMap<>();
            out.keySet().forEach(n -> incoming.put(n, 0));
            out.values().forEach(targets -> targets.keySet().forEach(t -> incoming.merge(t, 1, Integer::sum)));
            PriorityQueue<String> ready = new PriorityQueue<>(Comparator.naturalOrder());
            incoming.forEach((n, k) -> { if (k == 0) ready.add(n); });
            List<String> order = new ArrayList<>();
            while (!ready.isEmpty()) {
                String n = ready.poll();
                order.add(n);
                for (String t : out.get(n).keySet()) {
                    if (incoming.merge(t, -1, Integer::sum) == 0) {
                        ready.add(t);
                    }
                }
            }
            if (order.size() < out.size()) {
                throw new SystemOrderException("the systems' declarations form a cycle: " + findCycle(order));
            }
            return order;
        }

        private String findCycle(List<String> sorted) {
            Set<String> left = new LinkedHashSet<>(out.keySet());
            sorted.forEach(left::remove);
            // Every unsorted node still has an edge coming in from an unsorted node (else Kahn's algorithm would
            // have taken it), so walking backwards along such edges must repeat a node: that loop is a cycle.
            // Walking forwards could end at a node that merely follows a cycle.
            List<String> walk = new ArrayList<>();
            String n = left.iterator().next();
            while (!walk.contains(n)) {
                walk.add(n);
                String reached = n;
                n = left.stream().filter(p -> out.get(p).containsKey(reached)).findFirst().orElseThrow();
            }
            List<String> cycle = new ArrayList<>(walk.subList(walk.indexOf(n), walk.size()));
            Collections.reverse(cycle);
            cycle.add(cycle.get(0));
            StringBuilder s = new StringBuilder(String.join(" -> ", cycle)).append(" (");
            for (int i = 0; i + 1 < cycle.size(); i++) {
                s.append(i == 0 ? "" : "; ").append(out.get(cycle.get(i)).get(cycle.get(i + 1)));
            }
            return s.append(')').toString();
        }

        Map<String, List<String>> reasons() {
            Map<String, List<String>> byTarget = new LinkedHashMap<>();
            out.forEach((from, targets) -> targets.forEach((to, why) ->
                    byTarget.computeIfAbsent(to, k -> new ArrayList<>()).add(from + " (" + why + ")")));
            return byTarget;
        }
    }
}
