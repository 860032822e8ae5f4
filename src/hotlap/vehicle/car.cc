#include "hotlap/vehicle/car.h"

#include "hotlap/common/units.h"
#include "hotlap/common/yaml_reader.h"

namespace hotlap::vehicle {

Car LoadCar(const std::filesystem::path& path) {
  YamlReader y = YamlReader::Load(path);
  Car car;
  car.path = path;
  car.name = y.String("name");
  y.Choice("model", {"stock_car"});
  {
    YamlReader tyres = y.Map("tyres");
    for (Corner c : kAllCorners) {
      car.tyres[CornerIndex(c)] = tyre::LoadTyreFile(tyres.FilePath(CornerName(c)));
    }
    tyres.Finish();
  }
  {
    YamlReader brakes = y.Map("brakes");
    for (Corner c : kAllCorners) {
      car.brakes[CornerIndex(c)] = brake::LoadBrakeFile(brakes.FilePath(CornerName(c)));
    }
    brakes.Finish();
  }
  {
    YamlReader init = y.Map("initial_state");
    const Range temp = Range::Closed(-50.0, 1200.0, "degC");
    car.initial.tread_temp = CelsiusToKelvin(init.Number("tread_temp_C", temp));
    car.initial.carcass_temp = CelsiusToKelvin(init.Number("carcass_temp_C", temp));
    car.initial.disc_temp = CelsiusToKelvin(init.Number("disc_temp_C", temp));
    car.initial.calliper_temp = CelsiusToKelvin(init.Number("calliper_temp_C", temp));
    init.Finish();
  }
  y.Finish();
  return car;
}

}  // namespace hotlap::vehicle
