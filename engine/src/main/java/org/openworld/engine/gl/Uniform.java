package org.openworld.engine.gl;

import static org.lwjgl.opengl.GL20C.*;

import org.joml.Matrix3f;
import org.joml.Matrix3fc;
import org.joml.Matrix4f;
import org.joml.Matrix4fc;
import org.joml.Vector3fc;
import org.joml.Vector4fc;
import org.lwjgl.system.MemoryStack;

/**
 * A typed uniform handle, resolved once when its program links (CONTRIBUTING.md, "Uniforms") and again on a reload. Setting a value
 * needs the program bound ({@link ShaderProgram#use()}). Get one from {@link ShaderProgram#mat4} and its siblings.
 */
public abstract sealed class Uniform permits Uniform.Mat3, Uniform.Mat4, Uniform.Vec2, Uniform.Vec3, Uniform.Vec4, Uniform.Float, Uniform.Int {

    final String name;
    int location;
    /** The program it belongs to: a value set before the program first links is kept for the link. */
    ShaderProgram program;

    Uniform(String name) {
        this.name = name;
    }

    public String name() {
        return name;
    }

    /** Whether a value can be written now; if not, the caller hands it to {@link ShaderProgram#defer}. */
    boolean now() {
        return program == null || program.isLinked();
    }

    public static final class Mat3 extends Uniform {
        Mat3(String name) {
            super(name);
        }

        public void set(Matrix3fc value) {
            if (!now()) {
                Matrix3f copy = new Matrix3f(value);
                program.defer(() -> set(copy));
                return;
            }
            try (MemoryStack stack = MemoryStack.stackPush()) {
                glUniformMatrix3fv(location, false, value.get(stack.mallocFloat(9)));
            }
        }
    }

    public static final class Mat4 extends Uniform {
        Mat4(String name) {
            super(name);
        }

        public void set(Matrix4fc value) {
            if (!now()) {
                Matrix4f copy = new Matrix4f(value);
                program.defer(() -> set(copy));
                return;
            }
            try (MemoryStack stack = MemoryStack.stackPush()) {
                glUniformMatrix4fv(location, false, value.get(stack.mallocFloat(16)));
            }
        }
    }

    public static final class Vec2 extends Uniform {
        Vec2(String name) {
            super(name);
        }

        public void set(float x, float y) {
            if (!now()) {
                program.defer(() -> set(x, y));
                return;
            }
            glUniform2f(location, x, y);
        }
    }

    public static final class Vec3 extends Uniform {
        Vec3(String name) {
            super(name);
        }

        public void set(float x, float y, float z) {
            if (!now()) {
                program.defer(() -> set(x, y, z));
                return;
            }
            glUniform3f(location, x, y, z);
        }

        public void set(Vector3fc v) {
            set(v.x(), v.y(), v.z());
        }
    }

    public static final class Vec4 extends Uniform {
        Vec4(String name) {
            super(name);
        }

        public void set(float x, float y, float z, float w) {
            if (!now()) {
                program.defer(() -> set(x, y, z, w));
                return;
            }
            glUniform4f(location, x, y, z, w);
        }

        public void set(Vector4fc v) {
            set(v.x(), v.y(), v.z(), v.w());
        }

        /** A vec4 array from its first element on, four floats an element (elements the program lacks are ignored). */
        public void setArray(float[] values) {
            glUniform4fv(location, values);
        }
    }

    public static final class Float extends Uniform {
        Float(String name) {
            super(name);
        }

        public void set(float value) {
            if (!now()) {
                program.defer(() -> set(value));
                return;
            }
            glUniform1f(location, value);
        }
    }

    /** Integers, booleans (0/1) and samplers (the texture unit). */
    public static final class Int extends Uniform {
        Int(String name) {
            super(name);
        }

        public void set(int value) {
            if (!now()) {
                program.defer(() -> set(value));
                return;
            }
            glUniform1i(location, value);
        }
    }
}
