// Frames of a scene through the inverse-parameter array co-simulation (ip_cosim.hpp).
#include "ip_cosim.hpp"

namespace cig::cosim {
namespace {

// Power-on with the lattice's RGeps and no near plane (RGnear = MAX); each frame's setup then
// gives its RGeps and RGnear (1/near: the scene's near plane), written between two frames
// (IpCosim::configure) when they differ from the last frame's.
template <int W>
class IpFrameCosimImpl final : public IpFrameCosim {
 public:
  explicit IpFrameCosimImpl(IpRtl& rtl)
      : lattice_{rtl.n_pp(), 0}, cosim_(rtl, hls::Word<W>(invparam_eps_code(lattice_.size())), hls::word_max<W>()) {}
  IpFrameResult run(const ScreenFrame& frame, const invparam::ArrayPacing& pacing) override {
    const InvparamSetup<W> setup = invparam_setup<W>(frame, lattice_);
    const invparam::InvparamScene<W> scene = invparam::scene_of_setup(setup);
    const int columns = lattice_.size();
    if (setup.eps != cosim_.eps() || setup.tau_near != cosim_.tau_near()) cosim_.configure(setup.eps, setup.tau_near);
    IpFrameResult r = cosim_.run_frame(stream(scene), columns, pacing);
    r.faces = std::int64_t(scene.faces.size());
    return r;
  }
  std::int64_t model_cycles(const ScreenFrame& frame, const invparam::ArrayPacing& pacing) const override {
    const InvparamSetup<W> setup = invparam_setup<W>(frame, lattice_);
    return cosim_.model_cycles(stream(invparam::scene_of_setup(setup)), lattice_.size(), pacing, setup.eps,
                               setup.tau_near);
  }

 private:
  std::vector<invparam::StreamCode<W>> stream(const invparam::InvparamScene<W>& scene) const {
    return invparam::build_frame_stream(scene, lattice_.size(), cosim_.n_pp(), invparam::StreamMode::kFull);
  }
  InvparamLattice lattice_;  // L = N_PP (raster N_PP, one sample a pixel): setup_eps is -(L + 1)
  IpCosim<W> cosim_;
};

}  // namespace

std::string ip_hex(IpWord v) {
  const char* digits = "0123456789abcdef";
  std::string s;
  do {
    s.insert(s.begin(), digits[unsigned(v & 15u)]);
    v >>= 4;
  } while (v != 0);
  return "0x" + s;
}

// The harness of the seed's word whose registers the model has (the model knows its register
// width; IpCosim checks it again).
std::unique_ptr<IpFrameCosim> make_ip_frame_cosim(IpRtl& rtl) {
  if (rtl.register_bits() == hls::word_bits(64)) return std::make_unique<IpFrameCosimImpl<64>>(rtl);
  if (rtl.register_bits() == hls::word_bits(57)) return std::make_unique<IpFrameCosimImpl<57>>(rtl);
  throw std::logic_error("ip cosim: no harness for a model of W=" + std::to_string(rtl.register_bits()) +
                         " bits (registers of the seed's words 64 and 57: " + std::to_string(hls::word_bits(64)) +
                         ", " + std::to_string(hls::word_bits(57)) + ")");
}

}  // namespace cig::cosim
