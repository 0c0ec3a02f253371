// An OpenNI2 recording (.oni) made here, without a camera: OpenNI2's Recorder attached to
// the depth stream of its built-in "Dummy" device (320 × 240).
#pragma once

#include <gtest/gtest.h>

#include <OpenNI.h>
#include <string>

namespace dynamap::test {

// Records up to `frames` frames into `file`; the frames recorded go to `*recorded`.
// Failures are gtest assertions (call it under ASSERT_NO_FATAL_FAILURE).
inline void RecordDummyOni(const std::string& file, int frames, int* recorded) {
  *recorded = 0;
  ASSERT_EQ(openni::OpenNI::initialize(), openni::STATUS_OK);
  openni::Device device;
  ASSERT_EQ(device.open("Dummy"), openni::STATUS_OK);
  openni::VideoStream depth;
  ASSERT_EQ(depth.create(device, openni::SENSOR_DEPTH), openni::STATUS_OK);
  ASSERT_EQ(depth.start(), openni::STATUS_OK);
  openni::Recorder recorder;
  ASSERT_EQ(recorder.create(file.c_str()), openni::STATUS_OK);
  ASSERT_EQ(recorder.attach(depth, false), openni::STATUS_OK);
  ASSERT_EQ(recorder.start(), openni::STATUS_OK);
  for (int i = 0; i < frames; ++i) {
    openni::VideoStream* stream = &depth;
    int ready = -1;
    if (openni::OpenNI::waitForAnyStream(&stream, 1, &ready, 1000) != openni::STATUS_OK) break;
    openni::VideoFrameRef frame;
    if (depth.readFrame(&frame) != openni::STATUS_OK) break;
    ++*recorded;
  }
  recorder.stop();
  recorder.destroy();
  depth.stop();
  depth.destroy();
  device.close();
}

}  // namespace dynamap::test
