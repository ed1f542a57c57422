package dev.trisect;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.lang.reflect.Constructor;
import java.lang.reflect.Executable;
import java.lang.reflect.Field;
import java.lang.reflect.GenericArrayType;
import java.lang.reflect.Method;
import java.lang.reflect.Modifier;
import java.lang.reflect.ParameterizedType;
import java.lang.reflect.Type;
import java.lang.reflect.TypeVariable;
import java.lang.reflect.WildcardType;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.TreeSet;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

/**
 * The public API names only itself and the JDK: every public or protected signature of a public type
 * in an API package — supertypes, constructors, methods, fields, their generic arguments and the
 * exceptions they declare — uses primitive types, {@code java.*} and {@code javax.*} types, or types of
 * the API packages ({@link ArchitectureTest#API}; their subpackages, such as {@code scene.internal},
 * are internal). Otherwise a user could not call the API without reaching into internals, and the
 * module system (which exports the API packages alone) would reject the call.
 */
class ApiSignaturesTest {
    private static final Path CLASSES = Path.of("target/classes");

    @Test
    void apiSignaturesNameApiAndJdkTypesAlone() throws Exception {
        List<String> violations = new ArrayList<>();
        int types = 0;
        for (String pkg : ArchitectureTest.API) {
            for (Class<?> c : publicTypes(pkg)) {
                types++;
                check(c, violations);
            }
        }
        assertTrue(types > 30, "the check saw the API's types: " + types);
        assertEquals(List.of(), violations);
    }

    @Test
    void anInternalTypeInASignatureIsCaught() throws Exception {
        List<String> violations = new ArrayList<>();
        check(Leaky.class, violations);
        assertEquals(2, violations.size(), violations.toString());
    }

    /** A type that leaks an internal one twice: through a parameter and a generic return type. */
    public static final class Leaky {
        public void take(dev.trisect.pipeline.FrameRenderer r) {
        }

        public List<? extends dev.trisect.view.internal.FrameSlot> slots() {
            return List.of();
        }

        void packagePrivate(dev.trisect.pipeline.FrameRenderer r) {
        }
    }

    /** The public types (top level and nested) whose class files are in {@code dev.trisect.<pkg>} itself. */
    private static List<Class<?>> publicTypes(String pkg) throws IOException, ClassNotFoundException {
        Path dir = CLASSES.resolve("dev/trisect/" + pkg.replace('.', '/'));
        List<Class<?>> out = new ArrayList<>();
        if (!Files.isDirectory(dir)) {
            return out;
        }
        TreeSet<String> names = new TreeSet<>();
        try (Stream<Path> files = Files.list(dir)) {
            files.map(p -> p.getFileName().toString()).filter(n -> n.endsWith(".class"))
                    .filter(n -> !n.equals("package-info.class") && !n.equals("module-info.class"))
                    .forEach(names::add);
        }
        for (String n : names) {
            Class<?> c = Class.forName("dev.trisect." + pkg + "." + n.substring(0, n.length() - 6), false,
                    ApiSignaturesTest.class.getClassLoader());
            if (visible(c)) {
                out.add(c);
            }
        }
        return out;
    }

    /** Public, and (if nested) inside public types all the way out; not anonymous or local. */
    private static boolean visible(Class<?> c) {
        for (Class<?> k = c; k != null; k = k.getDeclaringClass()) {
            if (!Modifier.isPublic(k.getModifiers()) || k.isAnonymousClass() || k.isLocalClass()) {
                return false;
            }
        }
        return true;
    }

    private static void checkBounds(TypeVariable<?>[] variables, String where, List<String> violations) {
        for (TypeVariable<?> v : variables) {
            for (Type b : v.getBounds()) {
                checkType(b, where + " <" + v.getName() + " extends>", violations);
            }
        }
    }

    private static void check(Class<?> c, List<String> violations) {
        String where = c.getName();
        checkBounds(c.getTypeParameters(), where, violations);
        if (c.getGenericSuperclass() != null) {
            checkType(c.getGenericSuperclass(), where + " extends", violations);
        }
        for (Type i : c.getGenericInterfaces()) {
            checkType(i, where + " implements", violations);
        }
        boolean extendable = !Modifier.isFinal(c.getModifiers());
        for (Constructor<?> k : c.getDeclaredConstructors()) {
            if (exposed(k.getModifiers(), extendable)) {
                checkExecutable(k, where + "(constructor)", violations);
            }
        }
        for (Method m : c.getDeclaredMethods()) {
            if (!m.isSynthetic() && !m.isBridge() && exposed(m.getModifiers(), extendable)) {
                checkType(m.getGenericReturnType(), where + "." + m.getName() + " returns", violations);
                checkExecutable(m, where + "." + m.getName(), violations);
            }
        }
        for (Field f : c.getDeclaredFields()) {
            if (!f.isSynthetic() && exposed(f.getModifiers(), extendable)) {
                checkType(f.getGenericType(), where + "." + f.getName(), violations);
            }
        }
    }

    /** Public, or protected in a class a user may extend. */
    private static boolean exposed(int modifiers, boolean extendable) {
        return Modifier.isPublic(modifiers) || (extendable && Modifier.isProtected(modifiers));
    }

    private static void checkExecutable(Executable e, String where, List<String> violations) {
        checkBounds(e.getTypeParameters(), where, violations);
        for (Type p : e.getGenericParameterTypes()) {
            checkType(p, where + " takes", violations);
        }
        for (Type x : e.getGenericExceptionTypes()) {
            checkType(x, where + " throws", violations);
        }
    }

    private static void checkType(Type t, String where, List<String> violations) {
        if (t instanceof Class<?> c) {
            while (c.isArray()) {
                c = c.getComponentType();
            }
            if (!c.isPrimitive() && !allowed(c)) {
                violations.add(where + " " + c.getName());
            }
        } else if (t instanceof ParameterizedType p) {
            checkType(p.getRawType(), where, violations);
            for (Type a : p.getActualTypeArguments()) {
                checkType(a, where, violations);
            }
        } else if (t instanceof WildcardType w) {
            for (Type b : w.getUpperBounds()) {
                checkType(b, where, violations);
            }
            for (Type b : w.getLowerBounds()) {
                checkType(b, where, violations);
            }
        } else if (t instanceof GenericArrayType g) {
            checkType(g.getGenericComponentType(), where, violations);
        }
        // A type variable is checked where it is declared (its bounds), not where it is used: bounds
        // may name the variable itself (T extends Comparable<T>).
    }

    private static boolean allowed(Class<?> c) {
        String pkg = c.getPackageName();
        if (pkg.startsWith("java.") || pkg.startsWith("javax.")) {
            return true;
        }
        if (c.getEnclosingClass() == ApiSignaturesTest.class || c == ApiSignaturesTest.class) {
            return true;
        }
        return pkg.startsWith("dev.trisect.") && ArchitectureTest.API.contains(pkg.substring("dev.trisect.".length()));
    }
}
