// SPDX-License-Identifier: MIT
// ddfcam tests: hand-written valid path-file texts and the tokens mutations insert into them.
#include "fuzz_inputs.h"

namespace ddfcam::test {

std::vector<std::string> fuzzTokens(FuzzFormat format) {
  std::vector<std::string> tokens = {"\n",       "\r\n",     "\r",    ",",   " ",
                                     "\t",       "#",        "\"",    "'",   std::string(1, '\0'),
                                     "\xff\xfe", "\xc3\xa9", "1e308", "nan", "-"};
  std::vector<std::string> specific;
  switch (format) {
    case FuzzFormat::Csv:
      specific = {
          "path,point,contact_x_mm,contact_y_mm,contact_z_mm,axis_i,axis_j,axis_k,"
          "normal_x,normal_y,normal_z,feed_mm_per_min,move",
          "path_index,x,y,z,i,j,k",
          "x,y,z",
          "x,y,z,i,j,k",
          "cut",
          "link",
          "rapid",
          ",,,",
          "0,0,0",
          "0,0,0,0,0,0",
          ";",
          "# comment"};
      break;
    case FuzzFormat::Apt:
      specific = {"GOTO/",       "GOTO / ",         "$",       "$$",          "$\n",
                  "MULTAX/ON",   "MULTAX",          "CIRCLE/", "FEDRAT/",     "FEDRAT/MMPM,",
                  "FEDRAT/IPM,", ",MMPM",           ",IPM",    "UNITS/MM",    "UNITS/INCHES",
                  "UNIT/MM",     "RAPID",           "PARTNO ", "PARTNO/",     "CUTTER/",
                  "LOADTL/",     "SPINDL/RPM,",     "FROM/",   "FINI",        "END",
                  "COOLNT/ON",   "TLDATA/MILL,",    "0,0,0",   "0,0,0,0,0,0", "/",
                  ",,",          "GOTO/1,2,3,0,0,0"};
      break;
    case FuzzFormat::RosYaml:
      specific = {"- paths:",
                  "poses:",
                  "- position:",
                  "orientation:",
                  "x: ",
                  "y: ",
                  "z: ",
                  "w: ",
                  "header:",
                  "frame_id: ",
                  "seq: ",
                  "stamp:",
                  "  ",
                  "    ",
                  "- ",
                  "[",
                  "]",
                  "{",
                  "}",
                  ": ",
                  "---",
                  "...",
                  "&a ",
                  "*a",
                  "!!float ",
                  "|",
                  ">",
                  "~",
                  "null",
                  "x: 0\ny: 0\nz: 0\nw: 0",
                  std::string(200, '['),
                  std::string(64, ' ') + "- "};
      break;
    case FuzzFormat::FanucLs:
      specific = {"/PROG ",
                  "/ATTR",
                  "/MN",
                  "/POS",
                  "/END",
                  "P[",
                  "]",
                  "{",
                  "};",
                  "GP1:",
                  "UF : 0, UT : 1,",
                  "CONFIG : 'N U T, 0, 0, 0',",
                  "X =",
                  "Y =",
                  "Z =",
                  "W =",
                  "P =",
                  "R =",
                  " mm,",
                  " deg,",
                  ":L P[",
                  ":J P[",
                  "200mm/sec",
                  "100%",
                  "CNT60",
                  "FINE",
                  " ;",
                  "P[0]",
                  "P[-1]",
                  "P[99999999999]",
                  "X =\t",
                  "LINE_COUNT\t\t= 99999999999;"};
      break;
  }
  tokens.insert(tokens.end(), specific.begin(), specific.end());
  return tokens;
}

std::vector<std::string> builtinSeeds(FuzzFormat format) {
  switch (format) {
    case FuzzFormat::Csv:
      return {
          "path,point,contact_x_mm,contact_y_mm,contact_z_mm,axis_i,axis_j,axis_k,normal_x,"
          "normal_y,normal_z,feed_mm_per_min,move\n"
          "0,0,1.000000,2.000000,3.000000,1.000000,0.000000,0.000000,0.000000,0.000000,1.000000,"
          "500.000000,cut\n"
          "0,1,1.500000,2.000000,3.100000,0.000000,1.000000,0.000000,0.000000,0.000000,1.000000,"
          "500.000000,cut\n"
          "1,0,1.500000,2.000000,13.100000,0.000000,1.000000,0.000000,0.000000,0.000000,1.000000,"
          "0.000000,rapid\n"
          "2,0,4.250000,-2.500000,3.000000,0.000000,0.000000,1.000000,0.000000,0.000000,1.000000,"
          "500.000000,link\n",
          "path,point,tool_x_mm,tool_y_mm,tool_z_mm,axis_i,axis_j,axis_k,normal_x,normal_y,"
          "normal_z,feed_mm_per_min,move\r\n"
          "0,0,0.5,0.25,10,0.6,0,0.8,0,0,1,250,cut\r\n"
          "0,1,1.5,0.25,10.5,0.6,0,0.8,0,0,1,250,cut\r\n",
          "path_index,x,y,z,i,j,k\n0,0.605343,-0.122467,-0.052194,0.096173,-0.164257,0.981718\n"
          "0,0.514292,-0.127301,-0.047902,0.045996,-0.131428,0.990258\n"
          "1,-0.579831,-0.160854,-0.051443,-0.103779,-0.100868,0.989472\n",
          "1.0,2.0,3.0\n1.5,2.0,3.0\n2.0,2.5,3.25\n",
          "x,y,z,i,j,k\n10,20,30,0,0,1\n11,20,30,0,0.6,0.8\n12,21,29.5,0,0,1\n"};
    case FuzzFormat::Apt:
      return {
          "PARTNO/FUZZ SEED ONE\nUNITS/MM\nCUTTER/10.000000,5.000000,5.000000,5.000000,0.000000,"
          "0.000000,50.000000\nLOADTL/3\nSPINDL/RPM,3000.000000,CLW\nCOOLNT/ON\n"
          "$$ a comment line\nFEDRAT/500.000000,MMPM\nMULTAX/ON\nRAPID\n"
          "GOTO/0.0000,0.0000,50.0000,0.000000000,0.000000000,1.000000000\n"
          "GOTO/10.0000,0.0000,5.0000,0.000000000,0.000000000,1.000000000\n"
          "GOTO/20.0000,5.0000,5.5000,0.000000000,0.600000000,$\n   0.800000000\n"
          "GOTO / 30.0000, 5.0000, 6.0000, 0.0, 0.6, 0.8\nCOOLNT/OFF\nEND\nFINI\n",
          "TOOL PATH/FLOOR_FACING,TOOL,FACEMILL\nTLDATA/MILL,10.0000,0.0000,50.0000,0.0000,0.0000\n"
          "$$ centerline "
          "data\nPAINT/PATH\nRAPID\nGOTO/-2.5559,157.5807,43.0000,0.0000000,0.0000000,"
          "1.0000000\nFEDRAT/MMPM,250.0000\nGOTO/-2.5559,157.5807,25.8000\n"
          "GOTO/-2.5559,157.4997,25.8000\nCIRCLE/-0.0559,157.4997,25.8000,0.0000000,0.0000000,"
          "-1.0000000,2.5000,0.0600,0.5000,10.0000,0.0000\nGOTO/-0.0559,154.9997,25.8000\n"
          "GOTO/150.0409,154.9997,25.8000\nEND-OF-PATH\n",
          "$$*          Pro/CLfile  Vers 1.0\nPARTNO CORE_WORK\nMACHIN / MILL, M0001\n"
          "UNITS / INCHES\nLOADTL / 8\nSPINDL / RPM, 2000.000000,  CLW\n"
          "FROM / 0.0000, 0.0000, 3.7750\nRAPID \nGOTO / 4.6175, 8.2563, 3.7750\n"
          "FEDRAT / 10.000000,  IPM\nGOTO / 4.6175, 7.6380, 1.9579\nGOTO / 4.5984, 7.5398, 1.9694\n"
          "FINI\n"};
    case FuzzFormat::RosYaml:
      return {
          "- paths:\n"
          "    - header:\n        frame_id: 0\n        seq: 6\n      poses:\n"
          "        - position:\n            z: -0.05219445005059242\n"
          "            x: 0.6053426265716553\n            y: -0.122466504573822\n"
          "          orientation:\n            x: 0.08374666629252535\n"
          "            y: 0.04612385787875842\n            z: 0.02614605483127292\n"
          "            w: 0.9950756113504746\n"
          "        - position:\n            x: 0.5142921805381775\n"
          "            y: -0.1273010224103928\n            z: -0.04790230095386505\n"
          "          orientation:\n            y: 0.02172948982117267\n"
          "            x: 0.06632327355339525\n            z: 0.0199877361274142\n"
          "            w: 0.9973612891685736\n"
          "    - header:\n        frame_id: 0\n      poses:\n"
          "        - position:\n            x: 0.1\n            y: 0.2\n            z: 0.3\n"
          "          orientation:\n            x: 0\n            y: 0\n            z: 0\n"
          "            w: 1\n"};
    case FuzzFormat::FanucLs:
      return {
          "/PROG  FUZZ_SEED\n/ATTR\nOWNER\t\t= MNEDITOR;\nCOMMENT\t\t= \"\";\n"
          "LINE_COUNT\t= 3;\nDEFAULT_GROUP\t= 1,*,*,*,*;\n/MN\n\t1:  UFRAME_NUM=0 ;\n"
          "\t2:J P[1] 100% CNT60 \t;\n\t3:L P[2] 200mm/sec CNT60 \t;\n/POS\nP[1]{\n   GP1:\n"
          "\tUF : 0, UT : 1,\t\tCONFIG : 'N U T, 0, 0, 0',\n"
          "\tX =\t653.350855\tmm,\tY =\t600.959864\tmm,\tZ =\t660.701574\tmm,\n"
          "\tW =\t4.261677\tdeg,\tP =\t13.559316\tdeg,\tR =\t12.082948\tdeg\n};\nP[2]{\n"
          "   GP1:\n\tUF : 0, UT : 1,\t\tCONFIG : 'N U T, 0, 0, 0',\n"
          "\tX =\t669.002648\tmm,\tY =\t558.748509\tmm,\tZ =\t847.687800\tmm,\n"
          "\tW =\t12.096094\tdeg,\tP =\t19.311778\tdeg,\tR =\t14.653627\tdeg\n};\n/END\n"};
  }
  return {};
}

}  // namespace ddfcam::test
