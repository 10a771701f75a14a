#include "output/readings_sink.h"

#include "output/npy_writer.h"
#include "output/readings_csv.h"

namespace proxsim {

std::unique_ptr<RunSink> MakeReadingsSink(ReadingsFormat format, const std::string& out_dir, const Scenario& scenario,
                                          std::vector<std::string> object_names) {
  switch (format) {
    case ReadingsFormat::kNpy: return std::make_unique<NpyReadingsWriter>(out_dir, scenario, std::move(object_names));
    case ReadingsFormat::kCsv: break;
  }
  return std::make_unique<ReadingsCsvWriter>(out_dir, scenario, std::move(object_names));
}

}  // namespace proxsim
