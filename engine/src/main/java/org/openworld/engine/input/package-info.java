/**
 * User input as a world resource ({@link org.openworld.engine.input.InputState}): the window fills it from GLFW
 * callbacks, systems read it in their fixed-step update. Headless runs leave it empty.
 */
package org.openworld.engine.input;
