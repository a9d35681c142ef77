// vsOpenVDBText.h — text read from a .vdb file, made fit for vtkOpenVDBVolumeReader's messages.
// Grid names and OpenVDB's exception texts come from a file that may be corrupt, so they can hold
// any bytes; Python observers decode the messages as UTF-8. Internal to VisSweep::Filters
// (hidden from the wrappers).
#ifndef vsOpenVDBText_h
#define vsOpenVDBText_h

#if !defined(__VTK_WRAP__)
#include <exception>
#include <string>

namespace vs
{
/** Text for a message: valid UTF-8 is kept, other bytes and control characters become '?'
 *  (names read from a corrupt file can be anything; Python observers decode messages). */
std::string Printable(const std::string& s);

/** `s` printable, in double quotes. */
std::string Quote(const std::string& s);

/** An exception's text, printable ("out of memory (a corrupt size?)" for std::bad_alloc). */
std::string Describe(const std::exception& e);
}
#endif

#endif
