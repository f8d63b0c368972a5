// The Model menu's dialogs as field lists: keyword, label, unit, initial value, tip, and what a
// naming field offers; 2D and 3D forms.
#include "dialog_specs.hpp"

namespace tessera::ui {

namespace {
// Grouted cables: the properties every cable dialog shares (per cable in 3D; 2D models take a
// row spacing out of the plane).
std::vector<CommandField> cable_fields(bool three) {
  std::vector<CommandField> f{
      {"segments", "Segments", "", "8", "nodes at both ends of each"},
      {"ea", "Axial stiffness E A", "N", "1e8",
       three ? "" : "per cable; divided by the row spacing"},
      {"tension", "Yield force in tension", "N", "5e5", "empty: none"},
      {"kbond", "Grout shear stiffness", "N/m/m", "1e8", "per metre of cable"},
      {"sbond", "Grout bond strength", "N/m", "2e5", "per metre of cable; 0: none"},
      {"sfriction", "Grout friction angle", "deg", "",
       "bond strength rising with confinement (zones)"},
      {"perimeter", "Grout perimeter", "m", "", "with the friction angle"},
      {"pretension", "Pretension", "N", "", "empty: none"},
      {"free", "Free (unbonded) length", "m", "", "from the head"},
      {"head", "Faceplate at the head", "", "off", "on: tied to the rock"},
      {"rowspacing", "Row spacing (out of plane)", "m", "1", ""},
      {"name", "Name", "", "", "for histories"}};
  if (three) std::erase_if(f, [](const CommandField& c) { return c.key == "rowspacing"; });
  return f;
}

DialogSpec spec(const QString& name) {
  const QString msd = "a mean, or mean,sd for a normal spread";
  if (name == "material")
    return {"Material",
            "material define",
            {{"#name", "Name", "", "rock", "the name scripts and assignments use"},
             {"density", "Density", "kg/m³", "2600", ""},
             {"E", "Young's modulus", "Pa", "", "deformable blocks only"},
             {"nu", "Poisson's ratio", "", "", ""},
             {"model", "Zone model", "", "", "empty: elastic", "zone models"},
             {"friction", "Friction angle", "deg", "", ""},
             {"cohesion", "Cohesion", "Pa", "", ""},
             {"tension", "Tensile strength", "Pa", "", ""},
             {"dilation", "Dilation angle", "deg", "", ""},
             {"ctable", "Cohesion table (strain-softening)", "", "", "strain,Pa pairs"},
             {"ftable", "Friction table (strain-softening)", "", "", "strain,deg pairs"},
             {"jfriction", "Joint friction (ubiquitous-joint)", "deg", "", ""},
             {"jcohesion", "Joint cohesion (ubiquitous-joint)", "Pa", "", ""},
             {"jangle", "Plane angle from x (2D)", "deg", "",
              "ubiquitous-joint, transversely-isotropic"},
             {"jdip", "Plane dip (3D)", "deg", "", ""},
             {"jdipdir", "Plane dip direction (3D)", "deg", "", "clockwise from north (+y)"},
             {"E1", "E in the plane (transversely-isotropic)", "Pa", "", "instead of E and nu"},
             {"E3", "E across the plane", "Pa", "", ""},
             {"nu12", "Poisson's ratio in the plane", "", "", ""},
             {"nu13", "Poisson's ratio across", "", "", ""},
             {"G13", "Shear modulus across", "Pa", "", ""}}};
  if (name == "joint")
    return {"Joint properties",
            "joint define",
            {{"#name", "Name", "", "joints", ""},
             {"kn", "Normal stiffness", "Pa/m", "1e10", ""},
             {"ks", "Shear stiffness", "Pa/m", "1e10", ""},
             {"friction", "Friction angle", "deg", "30", ""},
             {"cohesion", "Cohesion", "Pa", "", ""},
             {"tension", "Tensile strength", "Pa", "", ""},
             {"dilation", "Dilation angle", "deg", "", ""},
             {"law", "Joint law", "", "", "empty: coulomb", "joint laws"},
             {"ifriction", "Initial friction (cy)", "deg", "", "decays to the friction angle"},
             {"roughness", "Roughness length (cy)", "m", "", "plastic shear to lose roughness"},
             {"jrc", "JRC (barton-bandis)", "", "", "joint roughness coefficient"},
             {"jcs", "JCS (barton-bandis)", "Pa", "", "joint wall compressive strength"},
             {"vm", "Maximum closure (barton-bandis)", "m", "", "kn is then the initial stiffness"},
             {"dpeak", "Shear at peak (barton-bandis)", "m", "", "empty: Barton's for 1 m"}}};
  if (name == "jset")
    return {"Joint set",
            "jset",
            {{"angle", "Angle from x", "deg", "30", msd},
             {"spacing", "Spacing", "m", "1", msd},
             {"trace", "Trace length", "m", "", "empty: traces run through; " + msd},
             {"gap", "Gap (rock bridge)", "m", "", msd},
             {"origin", "A trace through", "x,y m", "", ""},
             {"seed", "Random seed", "", "", ""},
             {"!extend", "Trace ends run to block edges", "", "", ""},
             {"name", "Name", "", "", "the joints' name for properties and selections"}},
            true};
  const CommandField core_name{"name", "Name", "", "", "the opening's joints, e.g. for pressure"};
  const CommandField core{"group", "Group of the core", "", "tunnel",
                          "excavate it with delete group=..."};
  if (name == "tunnel")
    return {"Circular opening",
            "tunnel circle",
            {{"centre", "Centre", "x,y m", "0,0", ""},
             {"radius", "Radius", "m", "1", ""},
             {"segments", "Segments", "", "24", ""},
             core_name,
             core}};
  if (name == "horseshoe")
    return {"Horseshoe opening",
            "tunnel horseshoe",
            {{"centre", "Middle of the floor", "x,y m", "0,0", ""},
             {"width", "Width", "m", "6", ""},
             {"height", "Height", "m", "6", "walls plus the half-circle roof"},
             {"segments", "Roof segments", "", "12", ""},
             core_name,
             core}};
  if (name == "rectangle")
    return {"Rectangular opening",
            "tunnel rectangle",
            {{"#a", "A corner", "x,y m", "0,0", ""},
             {"#b", "The opposite corner", "x,y m", "4,3", ""},
             core_name,
             core}};
  // Rock bolts: the properties both dialogs share.
  const std::vector<CommandField> bolt_props{
      {"ka", "Axial stiffness", "N/m", "1e8", "per bolt; divided by the row spacing"},
      {"ks", "Shear stiffness", "N/m", "1e7", ""},
      {"tension", "Yield force in tension", "N", "2e5", "empty: none"},
      {"shear", "Yield force in shear", "N", "1e5", "empty: none"},
      {"rupture", "Axial displacement at rupture", "m", "", "empty: never"},
      {"rowspacing", "Row spacing (out of plane)", "m", "1", ""},
      {"name", "Name", "", "", "for histories"}};
  if (name == "bolt") {
    DialogSpec s{"Rock bolt",
                 "bolt",
                 {{"#a", "From", "x,y m", "0,0", ""}, {"#b", "To", "x,y m", "0,3", ""}}};
    s.fields.insert(s.fields.end(), bolt_props.begin(), bolt_props.end());
    return s;
  }
  if (name == "boltpattern") {
    DialogSpec s{"Bolt pattern around an opening",
                 "bolt pattern",
                 {{"joints", "Opening", "", "", "its blocks deleted", "joint names"},
                  {"spacing", "Spacing along the wall", "m", "1.5", ""},
                  {"length", "Bolt length", "m", "4", ""},
                  {"angles", "Between angles", "deg", "", "e.g. 0,180; empty: all round"}}};
    s.fields.insert(s.fields.end(), bolt_props.begin(), bolt_props.end());
    return s;
  }
  const std::vector<CommandField> cable_props = cable_fields(false);
  if (name == "cable") {
    DialogSpec s{"Grouted cable",
                 "cable",
                 {{"#a", "From", "x,y m", "0,0", "on the wall"}, {"#b", "To", "x,y m", "0,4", ""}}};
    s.fields.insert(s.fields.end(), cable_props.begin(), cable_props.end());
    return s;
  }
  if (name == "cablepattern") {
    DialogSpec s{"Cable pattern around an opening",
                 "cable pattern",
                 {{"joints", "Opening", "", "", "its blocks deleted", "joint names"},
                  {"spacing", "Spacing along the wall", "m", "1.5", ""},
                  {"length", "Cable length", "m", "6", ""},
                  {"angles", "Between angles", "deg", "", "e.g. 0,180; empty: all round"}}};
    s.fields.insert(s.fields.end(), cable_props.begin(), cable_props.end());
    return s;
  }
  if (name == "liner")
    return {"Liner on an opening's wall",
            "liner",
            {{"joints", "Opening", "", "", "its blocks deleted", "joint names"},
             {"angles", "Between angles", "deg", "", "e.g. 0,180; empty: a closed ring"},
             {"e", "Young's modulus", "Pa", "30e9", "or give ea= and ei= in the script"},
             {"nu", "Poisson's ratio", "", "0.2", ""},
             {"thickness", "Thickness", "m", "0.2", ""},
             {"thrust", "Thrust capacity", "N", "", "per metre; empty: none"},
             {"moment", "Moment capacity", "N m", "", "per metre; empty: none"},
             {"kn", "Interface normal stiffness", "Pa/m", "1e10", ""},
             {"ks", "Interface shear stiffness", "Pa/m", "1e10", "0: full slip"},
             {"tension", "Interface tensile strength", "Pa", "", "empty: none"},
             {"cohesion", "Interface cohesion", "Pa", "", ""},
             {"friction", "Interface friction", "deg", "", ""},
             {"name", "Name", "", "", "for histories"}}};
  if (name == "region")
    return {"Region (a box to cut)",
            "region",
            {{"#a", "A corner", "x,y m", "0,0", ""},
             {"#b", "The opposite corner", "x,y m", "20,10", ""},
             {"group", "Group", "", "", "", "groups"},
             {"material", "Material", "", "", "", "materials"}}};
  if (name == "voronoi")
    return {"Voronoi cells",
            "voronoi",
            {{"size", "Mean cell size", "m", "0.5", ""},
             {"seed", "Random seed", "", "", ""},
             {"name", "Name", "", "", ""}},
            true};
  if (name == "wall")
    return {"Running-bond wall",
            "wall",
            {{"brick", "Brick", "L,H m", "0.4,0.2", ""},
             {"courses", "Courses", "", "10", ""},
             {"bricks", "Bricks per course", "", "8", ""},
             {"origin", "Bottom left", "x,y m", "0,0", ""},
             {"group", "Group", "", "wall", ""},
             {"material", "Material", "", "", "", "materials"}}};
  if (name == "arch")
    return {"Arch",
            "arch",
            {{"centre", "Centre of the intrados", "x,y m", "0,0", ""},
             {"radius", "Intrados radius", "m", "2", ""},
             {"thickness", "Ring thickness", "m", "0.3", ""},
             {"voussoirs", "Voussoirs", "", "15", ""},
             {"half_angle", "Half angle", "deg", "90", "90: semicircular"},
             {"abutment", "Abutment height", "m", "", ""},
             {"group", "Group", "", "arch", ""},
             {"material", "Material", "", "", "", "materials"}}};
  if (name == "zones")
    return {"Zones (deformable blocks)",
            "zone generate",
            {{"edge", "Zone edge", "m", "0.5", ""},
             {"fine", "Finer edge near a point", "m", "", ""},
             {"near", "Near", "x,y m", "", ""},
             {"radius", "Within", "m", "", ""},
             {"growth", "Growth away from it", "", "", "e.g. 0.3"},
             {"order", "Zone order", "1 or 2", "", "2: 10-node tetrahedra (3D models)"}},
            true};
  if (name == "boundary")
    return {"Boundary condition on nodes",
            "boundary",
            {{"fix", "Fix", "x, y or xy", "", ""},
             {"stress", "Applied stress", "SXX,SYY,SXY Pa", "", "tension positive"},
             {"pressure", "Pressure", "Pa", "", ""},
             {"joints", "Along joints named", "", "", "e.g. the opening's name", "joint names"}},
            true};
  if (name == "insitu")
    return {"In-situ stress",
            "insitu",
            {{"stress", "Stress", "SXX,SYY,SXY Pa", "-5e6,-10e6,0", "tension positive"},
             {"szz", "Out of plane", "Pa", "", "empty: nu (sxx + syy)"},
             {"ygradient", "Gradient with height", "Pa/m", "", "e.g. k rho g, rho g, 0"},
             {"y0", "Height of the given stress", "m", "", ""}}};
  if (name == "gravity")
    return {"Gravity",
            "gravity",
            {{"#gx", "Along x", "m/s²", "0", ""},
             {"#gy", "Along y", "m/s²", "-9.81", "2D: -9.81 (y up); 3D: 0"},
             {"#gz", "Along z", "m/s²", "", "3D models only: -9.81 (z up)"}}};
  if (name == "damping")
    return {"Damping",
            "damping",
            {{"#mode", "Kind", "", "local",
              "local or kinetic (static; kinetic is fastest), global (adaptive viscous) or none "
              "(dynamic analysis)"},
             {"#value", "Alpha or ratio", "", "",
              "local: alpha (default 0.8); kinetic: alpha (0.2); global: the power ratio removed "
              "(0.5)"}}};
  if (name == "fos")
    return {"Factor of safety",
            "solve fos",
            {{"joints", "Reduce the joints", "", "on", "on or off"},
             {"zones", "Reduce the zones", "", "on", "on or off"},
             {"ratio", "Equilibrium ratio", "", "1e-5", "a trial stands once it reaches this"},
             {"cycles", "Cycles per trial", "", "20000",
              "a trial not standing by then and still moving has failed"}}};
  if (name == "assign")
    return {"Assign to the selection",
            "",
            {{"group", "Group", "", "", "puts the selected blocks into this group", "groups"},
             {"material", "Material", "", "", "gives them this material", "materials"},
             {"joint", "Joint properties", "", "", "between the selected blocks (needs the group)",
              "joint properties"}}};
  return {};
}

// The 3D forms of the dialogs whose commands differ in 3D (points x,y,z; planes by dip and dip
// direction); the others as in 2D, and none for commands of 2D models only.
DialogSpec spec3(const QString& name) {
  const QString msd = "a mean, or mean,sd for a normal spread";
  const CommandField group{"group", "Group", "", "", "", "groups"};
  const CommandField material{"material", "Material", "", "", "", "materials"};
  const CommandField name_field{"name", "Name", "", "", "the joints' name for properties"};
  if (name == "box")
    return {"Block (box)",
            "block box",
            {{"#a", "A corner", "x,y,z m", "0,0,0", ""},
             {"#b", "The opposite corner", "x,y,z m", "10,10,10", ""},
             group,
             material}};
  if (name == "prism")
    return {"Block (prism)",
            "block prism",
            {{"#base", "Base polygon", "x,y x,y ... m", "0,0 4,0 4,3 0,3",
              "a convex polygon, corners separated by spaces"},
             {"z", "From z to z", "z0,z1 m", "0,2", ""},
             group,
             material}};
  if (name == "region")
    return {"Region (a box to cut)",
            "region",
            {{"#a", "A corner", "x,y,z m", "0,0,0", ""},
             {"#b", "The opposite corner", "x,y,z m", "20,20,20", ""},
             group,
             material}};
  if (name == "crack")
    return {"Crack (a plane)",
            "crack",
            {{"dip", "Dip", "deg", "60", "from horizontal"},
             {"ddir", "Dip direction", "deg", "90", "clockwise from north (+y)"},
             {"origin", "Through", "x,y,z m", "0,0,0", ""},
             {"radius", "Disc radius", "m", "", "empty: the whole plane"},
             name_field},
            true};
  if (name == "jset")
    return {"Joint set",
            "jset",
            {{"dip", "Dip", "deg", "60", msd},
             {"ddir", "Dip direction", "deg", "90", msd},
             {"spacing", "Spacing", "m", "2", msd},
             {"origin", "A plane through", "x,y,z m", "", ""},
             {"persistence", "Persistence", "0 to 1", "", "the share of blocks a plane cuts"},
             {"seed", "Random seed", "", "", ""},
             name_field},
            true};
  const CommandField core{"group", "Group of the core", "", "tunnel",
                          "excavate it with delete group=... (with rounds: group_1, ...)"};
  const CommandField opening{"name", "Name", "", "", "the opening's joints, e.g. for pressure"};
  if (name == "tunnel" || name == "horseshoe") {
    DialogSpec s{name == "tunnel" ? "Circular opening" : "Horseshoe opening",
                 name == "tunnel" ? "tunnel circle" : "tunnel horseshoe",
                 {{"centre", name == "tunnel" ? "Portal centre" : "Middle of the portal floor",
                   "x,y,z m", "0,0,0", ""},
                  {"axis", "Axis", "dx,dy,dz", "0,1,0", "the direction it runs"},
                  {"length", "Length", "m", "10", ""}}};
    if (name == "tunnel")
      s.fields.push_back({"radius", "Radius", "m", "3", ""});
    else
      s.fields.insert(s.fields.end(), {{"width", "Width", "m", "6", ""},
                                       {"height", "Height", "m", "6", "walls plus the roof"}});
    s.fields.insert(s.fields.end(),
                    {{"segments", "Segments", "", name == "tunnel" ? "24" : "12", ""},
                     {"rounds", "Rounds of advance", "", "", "groups G_1 ... G_N"},
                     opening,
                     core,
                     {"!join", "Join the rock around it back into bodies", "", "on", ""}});
    return s;
  }
  if (name == "wall")
    return {"Running-bond wall",
            "wall",
            {{"brick", "Brick", "L,H,W m", "0.6,0.3,0.3", "along x, up z, thick along y"},
             {"courses", "Courses", "", "6", ""},
             {"bricks", "Bricks per course", "", "6", ""},
             {"origin", "Bottom corner", "x,y,z m", "0,0,0", ""},
             {"group", "Group", "", "wall", ""},
             material,
             name_field}};
  if (name == "zones")
    return {"Zones (deformable blocks)",
            "zone generate",
            {{"edge", "Zone edge", "m", "1", ""},
             {"fine", "Finer edge near a point", "m", "", ""},
             {"near", "Near", "x,y,z m", "", ""},
             {"radius", "Within", "m", "", ""},
             {"growth", "Growth away from it", "", "", "e.g. 0.3"},
             {"order", "Zone order", "1 or 2", "", "2: 10-node tetrahedra"}},
            true};
  const CommandField x{"x", "Box: x from, to", "m", "", "nodes inside the box"},
      y{"y", "y from, to", "m", "", ""}, z{"z", "z from, to", "m", "", ""};
  if (name == "boundary")
    return {"Boundary condition on nodes",
            "boundary",
            {{"fix", "Fix", "x, y, z, xy ... xyz", "", ""},
             {"velocity", "Velocity", "vx,vy,vz m/s", "", ""},
             {"stress", "Applied stress", "SXX,SYY,SZZ,SXY,SYZ,SXZ Pa", "", "tension positive"},
             {"pressure", "Pressure", "Pa", "", ""},
             {"joints", "Along joints named", "", "", "e.g. the opening's name", "joint names"},
             x,
             y,
             z}};
  if (name == "insitu")
    return {"In-situ stress",
            "insitu",
            {{"stress", "Stress", "SXX,SYY,SZZ,SXY,SYZ,SXZ Pa", "-10e6,-10e6,-10e6,0,0,0",
              "tension positive"},
             {"zgradient", "Gradient with height", "6 values, Pa/m", "", ""},
             {"z0", "Height of the given stress", "m", "", ""}}};
  if (name == "gravity")
    return {"Gravity",
            "gravity",
            {{"#gx", "Along x", "m/s²", "0", ""},
             {"#gy", "Along y", "m/s²", "0", ""},
             {"#gz", "Along z", "m/s²", "-9.81", "z up"}}};
  if (name == "cable") {
    DialogSpec s{
        "Grouted cable",
        "cable",
        {{"#a", "From", "x,y,z m", "0,0,0", "on the face"}, {"#b", "To", "x,y,z m", "0,4,0", ""}}};
    const std::vector<CommandField> props = cable_fields(true);
    s.fields.insert(s.fields.end(), props.begin(), props.end());
    return s;
  }
  if (name == "rectangle" || name == "voronoi" || name == "arch" || name == "bolt" ||
      name == "boltpattern" || name == "cablepattern" || name == "liner")
    return {};
  return spec(name);
}

}  // namespace

DialogSpec dialog_spec(const QString& name, bool three) {
  if (three) return spec3(name);
  // Commands of 3D models only.
  if (name == "box" || name == "prism" || name == "crack") return {};
  return spec(name);
}

}  // namespace tessera::ui
