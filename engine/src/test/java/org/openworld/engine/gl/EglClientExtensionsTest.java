package org.openworld.engine.gl;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/**
 * What the device mode asks of EGL's client extensions, without OpenGL: either name for listing devices, the device
 * platform, whole names only, and a refusal that says exactly what is missing and what the EGL reported.
 */
class EglClientExtensionsTest {

    /** Mesa's answer through glvnd, shortened. */
    private static final String MESA = "EGL_EXT_device_base EGL_EXT_device_enumeration EGL_EXT_device_query "
            + "EGL_EXT_platform_base EGL_KHR_client_get_all_proc_addresses EGL_EXT_client_extensions "
            + "EGL_KHR_debug EGL_EXT_platform_device EGL_MESA_platform_surfaceless";

    @Test
    void mesasListIsEnough() {
        assertNull(EglDevice.lacks(MESA));
    }

    @Test
    void theOlderDeviceBaseNameListsDevicesToo() {
        assertNull(EglDevice.lacks("EGL_EXT_platform_base EGL_EXT_device_base EGL_EXT_platform_device"));
        assertNull(EglDevice.lacks("EGL_EXT_device_enumeration  EGL_EXT_platform_device\n"),
                "extra blanks and a line end between names");
    }

    @Test
    void aMissingPlatformIsNamedAloneWithWhatTheEglReported() {
        String said = EglDevice.lacks("EGL_EXT_device_base EGL_KHR_debug");
        assertNotNull(said);
        assertTrue(said.startsWith("this EGL lacks EGL_EXT_platform_device;"), said);
        assertFalse(said.contains("lacks EGL_EXT_device_enumeration"), said);
        assertTrue(said.endsWith("its client extensions: EGL_EXT_device_base EGL_KHR_debug"), said);
    }

    @Test
    void aMissingDeviceListIsNamedWithBothOfItsNames() {
        String said = EglDevice.lacks("EGL_EXT_platform_device EGL_EXT_device_query");
        assertNotNull(said);
        assertTrue(said.startsWith("this EGL lacks EGL_EXT_device_enumeration (or EGL_EXT_device_base);"), said);
    }

    @Test
    void onlyWholeNamesCount() {
        String said = EglDevice.lacks("EGL_EXT_device_base_x EGL_EXT_platform_devices");
        assertNotNull(said);
        assertTrue(said.contains("lacks EGL_EXT_device_enumeration (or EGL_EXT_device_base) and "
                + "EGL_EXT_platform_device;"), said);
    }

    @Test
    void noClientExtensionsAtAllIsSaid() {
        String said = EglDevice.lacks(null);
        assertNotNull(said);
        assertTrue(said.endsWith("its client extensions: none"), said);
        assertTrue(EglDevice.lacks(" ").endsWith("its client extensions: none"));
    }
}
