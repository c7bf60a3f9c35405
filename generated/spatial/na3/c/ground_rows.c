/* GENERATED FILE - DO NOT EDIT. C code emitted by CasADi for ground_rows() of
 * generated/spatial/na3/ (see its model.py), plus its batched driver.
 * Regenerate with: python -m snakecg_derive.spatial --checked-in
 * spec sha256: 82d64716a2089350522ee6ce607152c94df1120870c00e7b42763fcf4d7df073
 * tools: sympy 1.14.0, casadi 3.8.2, jinja2 3.1.6
 */
/* How to prefix internal symbols */
#ifdef CASADI_CODEGEN_PREFIX
  #define CASADI_NAMESPACE_CONCAT(NS, ID) _CASADI_NAMESPACE_CONCAT(NS, ID)
  #define _CASADI_NAMESPACE_CONCAT(NS, ID) NS ## ID
  #define CASADI_PREFIX(ID) CASADI_NAMESPACE_CONCAT(CODEGEN_PREFIX, ID)
#else
  #define CASADI_PREFIX(ID) snakecg_sp3_ground_rows_ ## ID
#endif

#include <math.h>

#ifndef casadi_real
#define casadi_real double
#endif

#ifndef casadi_int
#define casadi_int long long int
#endif

/* Add prefix to internal symbols */
#define casadi_f0 CASADI_PREFIX(f0)
#define casadi_s0 CASADI_PREFIX(s0)
#define casadi_s1 CASADI_PREFIX(s1)
#define casadi_s2 CASADI_PREFIX(s2)
#define casadi_s3 CASADI_PREFIX(s3)
#define casadi_s4 CASADI_PREFIX(s4)
#define casadi_s5 CASADI_PREFIX(s5)
#define casadi_sq CASADI_PREFIX(sq)

/* Symbol visibility in DLLs */
#ifndef CASADI_SYMBOL_EXPORT
  #if defined(_WIN32) || defined(__WIN32__) || defined(__CYGWIN__)
    #if defined(STATIC_LINKED)
      #define CASADI_SYMBOL_EXPORT
    #else
      #define CASADI_SYMBOL_EXPORT __declspec(dllexport)
    #endif
  #elif defined(__GNUC__) && defined(GCC_HASCLASSVISIBILITY)
    #define CASADI_SYMBOL_EXPORT __attribute__ ((visibility ("default")))
  #else
    #define CASADI_SYMBOL_EXPORT
  #endif
#endif

casadi_real casadi_sq(casadi_real x) { return x*x;}

/* Configuration this file was compiled with */
CASADI_SYMBOL_EXPORT void snakecg_sp3_ground_rows_casadi_version(int* major, int* minor, int* patch) {
  *major = 3;
  *minor = 8;
  *patch = 2;
}
CASADI_SYMBOL_EXPORT int snakecg_sp3_ground_rows_casadi_int_size(void) { return (int) sizeof(casadi_int); }
CASADI_SYMBOL_EXPORT int snakecg_sp3_ground_rows_casadi_real_size(void) { return (int) sizeof(casadi_real); }

static const casadi_int casadi_s0[3] = {10, 1, 1};
static const casadi_int casadi_s1[3] = {9, 1, 1};
static const casadi_int casadi_s2[3] = {169, 1, 1};
static const casadi_int casadi_s3[3] = {12, 1, 1};
static const casadi_int casadi_s4[3] = {4, 9, 1};
static const casadi_int casadi_s5[3] = {4, 1, 1};

/* snakecg_sp3_ground_rows:(q[10],v[9],K[169],support_points[12])->(A[4x9],adot_v[4],height[4]) */
static int casadi_f0(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a000, a001, a002, a003, a004, a005, a006, a007, a008, a009, a010, a011;
  casadi_real a012, a013, a014, a015, a016, a017, a018, a019, a020, a021, a022, a023;
  casadi_real a024, a025, a026, a027, a028, a029, a030, a031, a032, a033, a034, a035;
  casadi_real a036, a037, a038, a039, a040, a041, a042, a043, a044, a045, a046, a047;
  casadi_real a048, a049, a050, a051, a052, a053, a054, a055, a056, a057, a058, a059;
  casadi_real a060, a061, a062, a063, a064, a065, a066, a067, a068, a069, a070, a071;
  casadi_real a072, a073, a074, a075, a076, a077, a078, a079, a080, a081, a082, a083;
  casadi_real a084, a085, a086, a087, a088, a089, a090, a091, a092, a093, a094, a095;
  casadi_real a096, a097, a098, a099, a100, a101;
  a000=-2.;
  a001=arg[0]? arg[0][6] : 0;
  a002=(a000*a001);
  a003=arg[0]? arg[0][4] : 0;
  a004=(a002*a003);
  a005=arg[0]? arg[0][3] : 0;
  a006=(2.*a005);
  a007=arg[0]? arg[0][5] : 0;
  a008=(a006*a007);
  a004=(a004+a008);
  if (res[0]!=0) res[0][0]=a004;
  if (res[0]!=0) res[0][1]=a004;
  if (res[0]!=0) res[0][2]=a004;
  if (res[0]!=0) res[0][3]=a004;
  a001=(2.*a001);
  a009=(a001*a005);
  a010=(2.*a003);
  a010=(a010*a007);
  a009=(a009+a010);
  if (res[0]!=0) res[0][4]=a009;
  if (res[0]!=0) res[0][5]=a009;
  if (res[0]!=0) res[0][6]=a009;
  if (res[0]!=0) res[0][7]=a009;
  a011=1.;
  a012=casadi_sq(a005);
  a012=(a000*a012);
  a012=(a011+a012);
  a013=casadi_sq(a003);
  a013=(a000*a013);
  a014=(a012+a013);
  if (res[0]!=0) res[0][8]=a014;
  if (res[0]!=0) res[0][9]=a014;
  if (res[0]!=0) res[0][10]=a014;
  if (res[0]!=0) res[0][11]=a014;
  a011=(a011+a013);
  a013=casadi_sq(a007);
  a000=(a000*a013);
  a011=(a011+a000);
  a013=(a001*a007);
  a006=(a006*a003);
  a013=(a013+a006);
  a015=arg[3]? arg[3][0] : 0;
  a016=(a013*a015);
  a012=(a012+a000);
  a000=arg[3]? arg[3][1] : 0;
  a017=(a012*a000);
  a016=(a016+a017);
  a005=(a002*a005);
  a005=(a005+a010);
  a010=arg[3]? arg[3][2] : 0;
  a017=(a005*a010);
  a016=(a016+a017);
  a017=(a011*a016);
  a018=(a011*a015);
  a002=(a002*a007);
  a002=(a002+a006);
  a006=(a002*a000);
  a018=(a018+a006);
  a001=(a001*a003);
  a001=(a001+a008);
  a008=(a001*a010);
  a018=(a018+a008);
  a008=(a013*a018);
  a017=(a017-a008);
  if (res[0]!=0) res[0][12]=a017;
  a017=arg[2]? arg[2][103] : 0;
  a008=(a017*a013);
  a003=arg[2]? arg[2][104] : 0;
  a006=(a003*a012);
  a008=(a008+a006);
  a006=arg[2]? arg[2][105] : 0;
  a007=(a006*a005);
  a008=(a008+a007);
  a007=arg[2]? arg[2][76] : 0;
  a019=arg[3]? arg[3][3] : 0;
  a007=(a007*a019);
  a020=arg[2]? arg[2][77] : 0;
  a021=arg[3]? arg[3][4] : 0;
  a020=(a020*a021);
  a007=(a007+a020);
  a020=arg[2]? arg[2][78] : 0;
  a022=arg[3]? arg[3][5] : 0;
  a020=(a020*a022);
  a007=(a007+a020);
  a020=(a008*a007);
  a023=arg[2]? arg[2][97] : 0;
  a024=(a023*a013);
  a025=arg[2]? arg[2][98] : 0;
  a026=(a025*a012);
  a024=(a024+a026);
  a026=arg[2]? arg[2][99] : 0;
  a027=(a026*a005);
  a024=(a024+a027);
  a027=arg[0]? arg[0][7] : 0;
  a028=cos(a027);
  a029=(a024*a028);
  a030=arg[2]? arg[2][100] : 0;
  a031=(a030*a013);
  a032=arg[2]? arg[2][101] : 0;
  a033=(a032*a012);
  a031=(a031+a033);
  a033=arg[2]? arg[2][102] : 0;
  a034=(a033*a005);
  a031=(a031+a034);
  a027=sin(a027);
  a034=(a031*a027);
  a029=(a029+a034);
  a034=arg[2]? arg[2][70] : 0;
  a034=(a034*a019);
  a035=arg[2]? arg[2][71] : 0;
  a035=(a035*a021);
  a034=(a034+a035);
  a035=arg[2]? arg[2][72] : 0;
  a035=(a035*a022);
  a034=(a034+a035);
  a035=(a029*a034);
  a020=(a020+a035);
  a031=(a031*a028);
  a024=(a024*a027);
  a031=(a031-a024);
  a024=arg[2]? arg[2][73] : 0;
  a024=(a024*a019);
  a019=arg[2]? arg[2][74] : 0;
  a019=(a019*a021);
  a024=(a024+a019);
  a019=arg[2]? arg[2][75] : 0;
  a019=(a019*a022);
  a024=(a024+a019);
  a019=(a031*a024);
  a020=(a020+a019);
  a019=arg[2]? arg[2][124] : 0;
  a022=(a013*a019);
  a021=arg[2]? arg[2][125] : 0;
  a035=(a012*a021);
  a022=(a022+a035);
  a035=arg[2]? arg[2][126] : 0;
  a036=(a005*a035);
  a022=(a022+a036);
  a036=arg[0]? arg[0][1] : 0;
  a037=(a022+a036);
  a038=(a020+a037);
  a038=(a038-a036);
  a039=(a011*a038);
  a040=(a017*a011);
  a041=(a003*a002);
  a040=(a040+a041);
  a041=(a006*a001);
  a040=(a040+a041);
  a041=(a040*a007);
  a042=(a023*a011);
  a043=(a025*a002);
  a042=(a042+a043);
  a043=(a026*a001);
  a042=(a042+a043);
  a043=(a042*a028);
  a044=(a030*a011);
  a045=(a032*a002);
  a044=(a044+a045);
  a045=(a033*a001);
  a044=(a044+a045);
  a045=(a044*a027);
  a043=(a043+a045);
  a045=(a043*a034);
  a041=(a041+a045);
  a044=(a044*a028);
  a042=(a042*a027);
  a044=(a044-a042);
  a042=(a044*a024);
  a041=(a041+a042);
  a042=(a011*a019);
  a045=(a002*a021);
  a042=(a042+a045);
  a045=(a001*a035);
  a042=(a042+a045);
  a045=arg[0]? arg[0][0] : 0;
  a046=(a042+a045);
  a047=(a041+a046);
  a047=(a047-a045);
  a048=(a013*a047);
  a039=(a039-a048);
  if (res[0]!=0) res[0][13]=a039;
  a039=arg[2]? arg[2][114] : 0;
  a048=(a008*a039);
  a049=arg[2]? arg[2][112] : 0;
  a050=(a049*a029);
  a048=(a048+a050);
  a050=arg[2]? arg[2][113] : 0;
  a051=(a050*a031);
  a048=(a048+a051);
  a051=arg[2]? arg[2][85] : 0;
  a052=arg[3]? arg[3][6] : 0;
  a051=(a051*a052);
  a053=arg[2]? arg[2][86] : 0;
  a054=arg[3]? arg[3][7] : 0;
  a053=(a053*a054);
  a051=(a051+a053);
  a053=arg[2]? arg[2][87] : 0;
  a055=arg[3]? arg[3][8] : 0;
  a053=(a053*a055);
  a051=(a051+a053);
  a053=(a048*a051);
  a056=arg[2]? arg[2][108] : 0;
  a057=(a008*a056);
  a058=arg[2]? arg[2][106] : 0;
  a059=(a058*a029);
  a057=(a057+a059);
  a059=arg[2]? arg[2][107] : 0;
  a060=(a059*a031);
  a057=(a057+a060);
  a060=arg[0]? arg[0][8] : 0;
  a061=cos(a060);
  a062=(a057*a061);
  a063=arg[2]? arg[2][111] : 0;
  a064=(a008*a063);
  a065=arg[2]? arg[2][109] : 0;
  a066=(a065*a029);
  a064=(a064+a066);
  a066=arg[2]? arg[2][110] : 0;
  a067=(a066*a031);
  a064=(a064+a067);
  a060=sin(a060);
  a067=(a064*a060);
  a062=(a062+a067);
  a067=arg[2]? arg[2][79] : 0;
  a067=(a067*a052);
  a068=arg[2]? arg[2][80] : 0;
  a068=(a068*a054);
  a067=(a067+a068);
  a068=arg[2]? arg[2][81] : 0;
  a068=(a068*a055);
  a067=(a067+a068);
  a068=(a062*a067);
  a053=(a053+a068);
  a064=(a064*a061);
  a057=(a057*a060);
  a064=(a064-a057);
  a057=arg[2]? arg[2][82] : 0;
  a057=(a057*a052);
  a052=arg[2]? arg[2][83] : 0;
  a052=(a052*a054);
  a057=(a057+a052);
  a052=arg[2]? arg[2][84] : 0;
  a052=(a052*a055);
  a057=(a057+a052);
  a052=(a064*a057);
  a053=(a053+a052);
  a052=arg[2]? arg[2][129] : 0;
  a055=(a008*a052);
  a054=arg[2]? arg[2][127] : 0;
  a029=(a029*a054);
  a055=(a055+a029);
  a029=arg[2]? arg[2][128] : 0;
  a031=(a031*a029);
  a055=(a055+a031);
  a031=(a055+a037);
  a068=(a053+a031);
  a069=(a068-a036);
  a070=(a011*a069);
  a071=(a040*a039);
  a072=(a049*a043);
  a071=(a071+a072);
  a072=(a050*a044);
  a071=(a071+a072);
  a072=(a071*a051);
  a073=(a040*a056);
  a074=(a058*a043);
  a073=(a073+a074);
  a074=(a059*a044);
  a073=(a073+a074);
  a074=(a073*a061);
  a075=(a040*a063);
  a076=(a065*a043);
  a075=(a075+a076);
  a076=(a066*a044);
  a075=(a075+a076);
  a076=(a075*a060);
  a074=(a074+a076);
  a076=(a074*a067);
  a072=(a072+a076);
  a075=(a075*a061);
  a073=(a073*a060);
  a075=(a075-a073);
  a073=(a075*a057);
  a072=(a072+a073);
  a073=(a040*a052);
  a043=(a043*a054);
  a073=(a073+a043);
  a044=(a044*a029);
  a073=(a073+a044);
  a044=(a073+a046);
  a043=(a072+a044);
  a076=(a043-a045);
  a077=(a013*a076);
  a070=(a070-a077);
  if (res[0]!=0) res[0][14]=a070;
  a070=arg[2]? arg[2][123] : 0;
  a077=(a048*a070);
  a078=arg[2]? arg[2][121] : 0;
  a079=(a078*a062);
  a077=(a077+a079);
  a079=arg[2]? arg[2][122] : 0;
  a080=(a079*a064);
  a077=(a077+a080);
  a080=arg[2]? arg[2][94] : 0;
  a081=arg[3]? arg[3][9] : 0;
  a080=(a080*a081);
  a082=arg[2]? arg[2][95] : 0;
  a083=arg[3]? arg[3][10] : 0;
  a082=(a082*a083);
  a080=(a080+a082);
  a082=arg[2]? arg[2][96] : 0;
  a084=arg[3]? arg[3][11] : 0;
  a082=(a082*a084);
  a080=(a080+a082);
  a082=(a077*a080);
  a085=arg[2]? arg[2][117] : 0;
  a086=(a048*a085);
  a087=arg[2]? arg[2][115] : 0;
  a088=(a087*a062);
  a086=(a086+a088);
  a088=arg[2]? arg[2][116] : 0;
  a089=(a088*a064);
  a086=(a086+a089);
  a089=arg[0]? arg[0][9] : 0;
  a090=cos(a089);
  a091=(a086*a090);
  a092=arg[2]? arg[2][120] : 0;
  a093=(a048*a092);
  a094=arg[2]? arg[2][118] : 0;
  a095=(a094*a062);
  a093=(a093+a095);
  a095=arg[2]? arg[2][119] : 0;
  a096=(a095*a064);
  a093=(a093+a096);
  a089=sin(a089);
  a096=(a093*a089);
  a091=(a091+a096);
  a096=arg[2]? arg[2][88] : 0;
  a096=(a096*a081);
  a097=arg[2]? arg[2][89] : 0;
  a097=(a097*a083);
  a096=(a096+a097);
  a097=arg[2]? arg[2][90] : 0;
  a097=(a097*a084);
  a096=(a096+a097);
  a091=(a091*a096);
  a082=(a082+a091);
  a093=(a093*a090);
  a086=(a086*a089);
  a093=(a093-a086);
  a086=arg[2]? arg[2][91] : 0;
  a086=(a086*a081);
  a081=arg[2]? arg[2][92] : 0;
  a081=(a081*a083);
  a086=(a086+a081);
  a081=arg[2]? arg[2][93] : 0;
  a081=(a081*a084);
  a086=(a086+a081);
  a093=(a093*a086);
  a082=(a082+a093);
  a093=arg[2]? arg[2][132] : 0;
  a081=(a048*a093);
  a084=arg[2]? arg[2][130] : 0;
  a062=(a062*a084);
  a081=(a081+a062);
  a062=arg[2]? arg[2][131] : 0;
  a064=(a064*a062);
  a081=(a081+a064);
  a064=(a081+a031);
  a064=(a082+a064);
  a036=(a064-a036);
  a083=(a011*a036);
  a091=(a071*a070);
  a097=(a078*a074);
  a091=(a091+a097);
  a097=(a079*a075);
  a091=(a091+a097);
  a097=(a091*a080);
  a098=(a071*a085);
  a099=(a087*a074);
  a098=(a098+a099);
  a099=(a088*a075);
  a098=(a098+a099);
  a099=(a098*a090);
  a100=(a071*a092);
  a101=(a094*a074);
  a100=(a100+a101);
  a101=(a095*a075);
  a100=(a100+a101);
  a101=(a100*a089);
  a099=(a099+a101);
  a099=(a099*a096);
  a097=(a097+a099);
  a100=(a100*a090);
  a098=(a098*a089);
  a100=(a100-a098);
  a100=(a100*a086);
  a097=(a097+a100);
  a100=(a071*a093);
  a074=(a074*a084);
  a100=(a100+a074);
  a075=(a075*a062);
  a100=(a100+a075);
  a075=(a100+a044);
  a075=(a097+a075);
  a045=(a075-a045);
  a074=(a013*a045);
  a083=(a083-a074);
  if (res[0]!=0) res[0][15]=a083;
  a083=(a002*a016);
  a074=(a012*a018);
  a083=(a083-a074);
  if (res[0]!=0) res[0][16]=a083;
  a083=(a002*a038);
  a074=(a012*a047);
  a083=(a083-a074);
  if (res[0]!=0) res[0][17]=a083;
  a083=(a002*a069);
  a074=(a012*a076);
  a083=(a083-a074);
  if (res[0]!=0) res[0][18]=a083;
  a083=(a002*a036);
  a074=(a012*a045);
  a083=(a083-a074);
  if (res[0]!=0) res[0][19]=a083;
  a083=(a001*a016);
  a074=(a005*a018);
  a083=(a083-a074);
  if (res[0]!=0) res[0][20]=a083;
  a038=(a001*a038);
  a047=(a005*a047);
  a038=(a038-a047);
  if (res[0]!=0) res[0][21]=a038;
  a069=(a001*a069);
  a076=(a005*a076);
  a069=(a069-a076);
  if (res[0]!=0) res[0][22]=a069;
  a036=(a001*a036);
  a045=(a005*a045);
  a036=(a036-a045);
  if (res[0]!=0) res[0][23]=a036;
  a036=0.;
  if (res[0]!=0) res[0][24]=a036;
  a045=(a040*a020);
  a069=(a008*a041);
  a045=(a045-a069);
  if (res[0]!=0) res[0][25]=a045;
  a068=(a068-a037);
  a068=(a040*a068);
  a043=(a043-a046);
  a043=(a008*a043);
  a068=(a068-a043);
  if (res[0]!=0) res[0][26]=a068;
  a037=(a064-a037);
  a037=(a040*a037);
  a046=(a075-a046);
  a046=(a008*a046);
  a037=(a037-a046);
  if (res[0]!=0) res[0][27]=a037;
  if (res[0]!=0) res[0][28]=a036;
  if (res[0]!=0) res[0][29]=a036;
  a037=(a071*a053);
  a046=(a048*a072);
  a037=(a037-a046);
  if (res[0]!=0) res[0][30]=a037;
  a064=(a064-a031);
  a064=(a071*a064);
  a075=(a075-a044);
  a075=(a048*a075);
  a064=(a064-a075);
  if (res[0]!=0) res[0][31]=a064;
  if (res[0]!=0) res[0][32]=a036;
  if (res[0]!=0) res[0][33]=a036;
  if (res[0]!=0) res[0][34]=a036;
  a036=(a091*a082);
  a064=(a077*a097);
  a036=(a036-a064);
  if (res[0]!=0) res[0][35]=a036;
  a036=arg[1]? arg[1][3] : 0;
  a064=(a011*a036);
  a075=arg[1]? arg[1][4] : 0;
  a044=(a002*a075);
  a064=(a064+a044);
  a044=arg[1]? arg[1][5] : 0;
  a031=(a001*a044);
  a064=(a064+a031);
  a031=arg[1]? arg[1][0] : 0;
  a037=(a013*a031);
  a046=arg[1]? arg[1][1] : 0;
  a068=(a012*a046);
  a037=(a037+a068);
  a068=arg[1]? arg[1][2] : 0;
  a043=(a005*a068);
  a037=(a037+a043);
  a037=(a064*a037);
  a013=(a013*a036);
  a012=(a012*a075);
  a013=(a013+a012);
  a005=(a005*a044);
  a013=(a013+a005);
  a011=(a011*a031);
  a002=(a002*a046);
  a011=(a011+a002);
  a001=(a001*a068);
  a011=(a011+a001);
  a011=(a013*a011);
  a037=(a037-a011);
  a036=(a004*a036);
  a075=(a009*a075);
  a036=(a036+a075);
  a044=(a014*a044);
  a036=(a036+a044);
  a018=(a018*a036);
  a015=(a004*a015);
  a000=(a009*a000);
  a015=(a015+a000);
  a010=(a014*a010);
  a015=(a015+a010);
  a010=(a015*a064);
  a018=(a018-a010);
  a018=(a018*a064);
  a018=(a037+a018);
  a010=(a015*a013);
  a016=(a016*a036);
  a010=(a010-a016);
  a010=(a010*a013);
  a018=(a018-a010);
  if (res[1]!=0) res[1][0]=a018;
  a042=(a042*a036);
  a019=(a004*a019);
  a021=(a009*a021);
  a019=(a019+a021);
  a035=(a014*a035);
  a019=(a019+a035);
  a035=(a019*a064);
  a042=(a042-a035);
  a042=(a064*a042);
  a037=(a037+a042);
  a042=(a019*a013);
  a022=(a022*a036);
  a042=(a042-a022);
  a042=(a013*a042);
  a037=(a037-a042);
  a042=arg[1]? arg[1][6] : 0;
  a017=(a017*a004);
  a003=(a003*a009);
  a017=(a017+a003);
  a006=(a006*a014);
  a017=(a017+a006);
  a006=(a017*a013);
  a003=(a008*a036);
  a006=(a006-a003);
  a006=(a042*a006);
  a003=(a006*a020);
  a003=(a037+a003);
  a022=(a017*a042);
  a022=(a036+a022);
  a035=(a041*a022);
  a007=(a017*a007);
  a023=(a023*a004);
  a025=(a025*a009);
  a023=(a023+a025);
  a026=(a026*a014);
  a023=(a023+a026);
  a026=(a023*a028);
  a030=(a030*a004);
  a032=(a032*a009);
  a030=(a030+a032);
  a033=(a033*a014);
  a030=(a030+a033);
  a033=(a030*a027);
  a026=(a026+a033);
  a034=(a026*a034);
  a007=(a007+a034);
  a030=(a030*a028);
  a023=(a023*a027);
  a030=(a030-a023);
  a024=(a030*a024);
  a007=(a007+a024);
  a024=(a040*a042);
  a024=(a064+a024);
  a023=(a007*a024);
  a035=(a035-a023);
  a035=(a035*a024);
  a003=(a003+a035);
  a040=(a040*a036);
  a064=(a017*a064);
  a040=(a040-a064);
  a040=(a042*a040);
  a041=(a040*a041);
  a003=(a003-a041);
  a008=(a008*a042);
  a013=(a013+a008);
  a008=(a007*a013);
  a020=(a020*a022);
  a008=(a008-a020);
  a008=(a008*a013);
  a003=(a003-a008);
  if (res[1]!=0) res[1][1]=a003;
  a003=(a006*a055);
  a037=(a037+a003);
  a003=(a073*a022);
  a052=(a017*a052);
  a054=(a026*a054);
  a052=(a052+a054);
  a029=(a030*a029);
  a052=(a052+a029);
  a029=(a052*a024);
  a003=(a003-a029);
  a003=(a024*a003);
  a037=(a037+a003);
  a073=(a040*a073);
  a037=(a037-a073);
  a073=(a052*a013);
  a055=(a055*a022);
  a073=(a073-a055);
  a073=(a013*a073);
  a037=(a037-a073);
  a073=arg[1]? arg[1][7] : 0;
  a039=(a017*a039);
  a049=(a049*a026);
  a039=(a039+a049);
  a050=(a050*a030);
  a039=(a039+a050);
  a050=(a039*a013);
  a049=(a048*a022);
  a050=(a050-a049);
  a050=(a073*a050);
  a006=(a006+a050);
  a050=(a006*a053);
  a050=(a037+a050);
  a049=(a039*a073);
  a049=(a022+a049);
  a055=(a072*a049);
  a051=(a039*a051);
  a056=(a017*a056);
  a058=(a058*a026);
  a056=(a056+a058);
  a059=(a059*a030);
  a056=(a056+a059);
  a059=(a056*a061);
  a017=(a017*a063);
  a065=(a065*a026);
  a017=(a017+a065);
  a066=(a066*a030);
  a017=(a017+a066);
  a066=(a017*a060);
  a059=(a059+a066);
  a067=(a059*a067);
  a051=(a051+a067);
  a017=(a017*a061);
  a056=(a056*a060);
  a017=(a017-a056);
  a057=(a017*a057);
  a051=(a051+a057);
  a057=(a071*a073);
  a057=(a024+a057);
  a056=(a051*a057);
  a055=(a055-a056);
  a055=(a055*a057);
  a050=(a050+a055);
  a071=(a071*a022);
  a024=(a039*a024);
  a071=(a071-a024);
  a071=(a073*a071);
  a040=(a040+a071);
  a072=(a040*a072);
  a050=(a050-a072);
  a048=(a048*a073);
  a013=(a013+a048);
  a048=(a051*a013);
  a053=(a053*a049);
  a048=(a048-a053);
  a048=(a048*a013);
  a050=(a050-a048);
  if (res[1]!=0) res[1][2]=a050;
  a050=(a006*a081);
  a037=(a037+a050);
  a050=(a100*a049);
  a093=(a039*a093);
  a084=(a059*a084);
  a093=(a093+a084);
  a062=(a017*a062);
  a093=(a093+a062);
  a062=(a093*a057);
  a050=(a050-a062);
  a050=(a057*a050);
  a037=(a037+a050);
  a100=(a040*a100);
  a037=(a037-a100);
  a100=(a093*a013);
  a081=(a081*a049);
  a100=(a100-a081);
  a100=(a013*a100);
  a037=(a037-a100);
  a100=arg[1]? arg[1][8] : 0;
  a070=(a039*a070);
  a078=(a078*a059);
  a070=(a070+a078);
  a079=(a079*a017);
  a070=(a070+a079);
  a079=(a070*a013);
  a078=(a077*a049);
  a079=(a079-a078);
  a079=(a100*a079);
  a006=(a006+a079);
  a006=(a006*a082);
  a037=(a037+a006);
  a006=(a070*a100);
  a006=(a049+a006);
  a079=(a097*a006);
  a080=(a070*a080);
  a085=(a039*a085);
  a087=(a087*a059);
  a085=(a085+a087);
  a088=(a088*a017);
  a085=(a085+a088);
  a088=(a085*a090);
  a039=(a039*a092);
  a094=(a094*a059);
  a039=(a039+a094);
  a095=(a095*a017);
  a039=(a039+a095);
  a095=(a039*a089);
  a088=(a088+a095);
  a088=(a088*a096);
  a080=(a080+a088);
  a039=(a039*a090);
  a085=(a085*a089);
  a039=(a039-a085);
  a039=(a039*a086);
  a080=(a080+a039);
  a039=(a091*a100);
  a039=(a057+a039);
  a086=(a080*a039);
  a079=(a079-a086);
  a079=(a079*a039);
  a037=(a037+a079);
  a091=(a091*a049);
  a070=(a070*a057);
  a091=(a091-a070);
  a091=(a100*a091);
  a040=(a040+a091);
  a040=(a040*a097);
  a037=(a037-a040);
  a077=(a077*a100);
  a013=(a013+a077);
  a077=(a080*a013);
  a082=(a082*a006);
  a077=(a077-a082);
  a077=(a077*a013);
  a037=(a037-a077);
  if (res[1]!=0) res[1][3]=a037;
  a037=arg[0]? arg[0][2] : 0;
  a015=(a015+a037);
  if (res[2]!=0) res[2][0]=a015;
  a019=(a019+a037);
  a007=(a007+a019);
  if (res[2]!=0) res[2][1]=a007;
  a052=(a052+a019);
  a051=(a051+a052);
  if (res[2]!=0) res[2][2]=a051;
  a093=(a093+a052);
  a080=(a080+a093);
  if (res[2]!=0) res[2][3]=a080;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_sp3_ground_rows(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f0(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int snakecg_sp3_ground_rows_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void snakecg_sp3_ground_rows_release(int mem) {
}

CASADI_SYMBOL_EXPORT void snakecg_sp3_ground_rows_incref(void) {
}

CASADI_SYMBOL_EXPORT void snakecg_sp3_ground_rows_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int snakecg_sp3_ground_rows_n_in(void) { return 4;}

CASADI_SYMBOL_EXPORT casadi_int snakecg_sp3_ground_rows_n_out(void) { return 3;}

CASADI_SYMBOL_EXPORT casadi_real snakecg_sp3_ground_rows_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_sp3_ground_rows_name_in(casadi_int i) {
  switch (i) {
    case 0: return "q";
    case 1: return "v";
    case 2: return "K";
    case 3: return "support_points";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_sp3_ground_rows_name_out(casadi_int i) {
  switch (i) {
    case 0: return "A";
    case 1: return "adot_v";
    case 2: return "height";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_sp3_ground_rows_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    case 1: return casadi_s1;
    case 2: return casadi_s2;
    case 3: return casadi_s3;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_sp3_ground_rows_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s4;
    case 1: return casadi_s5;
    case 2: return casadi_s5;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int snakecg_sp3_ground_rows_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 4;
  if (sz_res) *sz_res = 3;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_sp3_ground_rows_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 4*sizeof(const casadi_real*);
  if (sz_res) *sz_res = 3*sizeof(casadi_real*);
  if (sz_iw) *sz_iw = 0*sizeof(casadi_int);
  if (sz_w) *sz_w = 0*sizeof(casadi_real);
  return 0;
}



/* ------------------------------------------------------------------------------------------
 * GENERATED FILE - DO NOT EDIT. Batched drivers rendered from derive/templates/batch.c.j2.
 * snakecg's counterpart of CasADi's Function.map(n, "serial"): one loop in C over n samples,
 * reading inputs in place (input k of sample i at arg[k] + i * stride[k]; stride 0 broadcasts)
 * and writing dense column-major outputs contiguously (output k of sample i at
 * res[k] + i * nnz_out(k)). Returns 0 on success, the failing sample + 1 otherwise, -1 when out of memory.
 * ---------------------------------------------------------------------------------------- */
#include <stdlib.h>

/* Cosines and sines of a block of angles in one loop without calls or branches, which the
 * compiler turns into vector instructions (16 angles per call): the sines and cosines of
 * the angles of 16 samples are computed at once, then the function without its own calls
 * runs per sample.
 * Reduction by pi/2 in three parts (Cody and Waite, exact products for |x| < 2^20 pi/2) and
 * fdlibm's polynomials of sin and cos on [-pi/4, pi/4] (errors below one unit in the last
 * place there); the quadrant turns the pair by n pi/2 with factors 0, +1, -1 (exact). An
 * angle with |x| above SNAKECG_SINCOS_MAX, or not a number, is left to the C library
 * (snakecg_sincos_large). */
#define SNAKECG_SINCOS_BLOCK 16
#define SNAKECG_SINCOS_MAX 8.0e5

#if defined(__GNUC__) && !defined(__clang__) && __GNUC__ >= 6 && defined(__x86_64__) \
    && defined(__linux__)
/* a second copy for processors with AVX2 (four angles per instruction), chosen at load time */
__attribute__((target_clones("avx2", "default")))
#endif
static void snakecg_sincos_block(const casadi_real* restrict x, casadi_real* restrict c,
                                 casadi_real* restrict s) {
  const casadi_real round = 6755399441055744.0; /* 1.5 * 2^52: adding it rounds to integers */
  const casadi_real two_over_pi = 6.36619772367581382433e-01;
  const casadi_real pio2_1 = 1.57079632673412561417e+00; /* pi/2: first 33 bits */
  const casadi_real pio2_2 = 6.07710050630396597660e-11; /* next 33 bits */
  const casadi_real pio2_3 = 2.02226624871116645580e-21; /* the rest */
  const casadi_real S1 = -1.66666666666666324348e-01, S2 = 8.33333333332248946124e-03,
      S3 = -1.98412698298579493134e-04, S4 = 2.75573137070700676789e-06,
      S5 = -2.50507602534068634195e-08, S6 = 1.58969099521155010221e-10;
  const casadi_real C1 = 4.16666666666666019037e-02, C2 = -1.38888888888741095749e-03,
      C3 = 2.48015872894767294178e-05, C4 = -2.75573143513906633035e-07,
      C5 = 2.08757232129817482790e-09, C6 = -1.13596475577881948265e-11;
  int i;
  for (i = 0; i < SNAKECG_SINCOS_BLOCK; ++i) {
    casadi_real n = (x[i] * two_over_pi + round) - round;  /* nearest multiple of pi/2 */
    casadi_real m = n - 4.0 * ((0.25 * n + round) - round); /* n mod 4 in -2..2 */
    casadi_real am = fabs(m);
    casadi_real cq = 1.0 - am, sq = m * (2.0 - am);          /* cos, sin of n pi/2 */
    casadi_real y = ((x[i] - n * pio2_1) - n * pio2_2) - n * pio2_3;
    casadi_real z = y * y;
    casadi_real sy = y + z * y * (S1 + z * (S2 + z * (S3 + z * (S4 + z * (S5 + z * S6)))));
    casadi_real hz = 0.5 * z, w = 1.0 - hz;
    casadi_real cy = w + (((1.0 - w) - hz)
                          + z * z * (C1 + z * (C2 + z * (C3 + z * (C4 + z * (C5 + z * C6))))));
    c[i] = cy * cq - sy * sq;
    s[i] = sy * cq + cy * sq;
  }
}

/* the C library's cos and sin where |x| > SNAKECG_SINCOS_MAX or x is not a number (the
 * driver calls this only when it met such an angle while gathering them) */
static void snakecg_sincos_large(const casadi_real* x, casadi_real* c, casadi_real* s,
                                 casadi_int n) {
  casadi_int i;
  for (i = 0; i < n; ++i) {
    if (!(fabs(x[i]) <= SNAKECG_SINCOS_MAX)) {
      c[i] = cos(x[i]);
      s[i] = sin(x[i]);
    }
  }
}

/* snakecg_sp3_ground_rows_sincos: 762 CasADi instructions, printed one per line */
static void snakecg_sp3_ground_rows_sincos(
    const casadi_real* restrict arg0,
    const casadi_real* restrict arg1,
    const casadi_real* restrict arg2,
    const casadi_real* restrict arg3,
    const casadi_real* restrict arg4,
    const casadi_real* restrict arg5,
    casadi_real* restrict res0,
    casadi_real* restrict res1,
    casadi_real* restrict res2) {
  casadi_real w0, w1, w2, w3, w4, w5, w6, w7, w8, w9;
  casadi_real w10, w11, w12, w13, w14, w15, w16, w17, w18, w19;
  casadi_real w20, w21, w22, w23, w24, w25, w26, w27, w28, w29;
  casadi_real w30, w31, w32, w33, w34, w35, w36, w37, w38, w39;
  casadi_real w40, w41, w42, w43, w44, w45, w46, w47, w48, w49;
  casadi_real w50, w51, w52, w53, w54, w55, w56, w57, w58, w59;
  casadi_real w60, w61, w62, w63, w64, w65, w66, w67, w68, w69;
  casadi_real w70, w71, w72, w73, w74, w75, w76, w77, w78, w79;
  casadi_real w80, w81, w82, w83, w84, w85, w86, w87, w88, w89;
  casadi_real w90, w91, w92, w93, w94, w95, w96, w97, w98, w99;
  casadi_real w100, w101;
  w0 = (-2.0);
  w1 = arg0[6];
  w2 = w0 * w1;
  w3 = arg0[4];
  w4 = w2 * w3;
  w5 = arg0[3];
  w6 = w5 + w5;
  w7 = arg0[5];
  w8 = w6 * w7;
  w4 = w4 + w8;
  res0[0] = w4;
  res0[1] = w4;
  res0[2] = w4;
  res0[3] = w4;
  w1 = w1 + w1;
  w9 = w1 * w5;
  w10 = w3 + w3;
  w10 = w10 * w7;
  w9 = w9 + w10;
  res0[4] = w9;
  res0[5] = w9;
  res0[6] = w9;
  res0[7] = w9;
  w11 = 1.0;
  w12 = w5 * w5;
  w12 = w0 * w12;
  w12 = w11 + w12;
  w13 = w3 * w3;
  w13 = w0 * w13;
  w14 = w12 + w13;
  res0[8] = w14;
  res0[9] = w14;
  res0[10] = w14;
  res0[11] = w14;
  w11 = w11 + w13;
  w13 = w7 * w7;
  w0 = w0 * w13;
  w11 = w11 + w0;
  w13 = w1 * w7;
  w6 = w6 * w3;
  w13 = w13 + w6;
  w15 = arg3[0];
  w16 = w13 * w15;
  w12 = w12 + w0;
  w0 = arg3[1];
  w17 = w12 * w0;
  w16 = w16 + w17;
  w5 = w2 * w5;
  w5 = w5 + w10;
  w10 = arg3[2];
  w17 = w5 * w10;
  w16 = w16 + w17;
  w17 = w11 * w16;
  w18 = w11 * w15;
  w2 = w2 * w7;
  w2 = w2 + w6;
  w6 = w2 * w0;
  w18 = w18 + w6;
  w1 = w1 * w3;
  w1 = w1 + w8;
  w8 = w1 * w10;
  w18 = w18 + w8;
  w8 = w13 * w18;
  w17 = w17 - w8;
  res0[12] = w17;
  w17 = arg2[103];
  w8 = w17 * w13;
  w3 = arg2[104];
  w6 = w3 * w12;
  w8 = w8 + w6;
  w6 = arg2[105];
  w7 = w6 * w5;
  w8 = w8 + w7;
  w7 = arg2[76];
  w19 = arg3[3];
  w7 = w7 * w19;
  w20 = arg2[77];
  w21 = arg3[4];
  w20 = w20 * w21;
  w7 = w7 + w20;
  w20 = arg2[78];
  w22 = arg3[5];
  w20 = w20 * w22;
  w7 = w7 + w20;
  w20 = w8 * w7;
  w23 = arg2[97];
  w24 = w23 * w13;
  w25 = arg2[98];
  w26 = w25 * w12;
  w24 = w24 + w26;
  w26 = arg2[99];
  w27 = w26 * w5;
  w24 = w24 + w27;
  w27 = arg4[0];
  w28 = w24 * w27;
  w29 = arg2[100];
  w30 = w29 * w13;
  w31 = arg2[101];
  w32 = w31 * w12;
  w30 = w30 + w32;
  w32 = arg2[102];
  w33 = w32 * w5;
  w30 = w30 + w33;
  w33 = arg5[0];
  w34 = w30 * w33;
  w28 = w28 + w34;
  w34 = arg2[70];
  w34 = w34 * w19;
  w35 = arg2[71];
  w35 = w35 * w21;
  w34 = w34 + w35;
  w35 = arg2[72];
  w35 = w35 * w22;
  w34 = w34 + w35;
  w35 = w28 * w34;
  w20 = w20 + w35;
  w30 = w30 * w27;
  w24 = w24 * w33;
  w30 = w30 - w24;
  w24 = arg2[73];
  w24 = w24 * w19;
  w19 = arg2[74];
  w19 = w19 * w21;
  w24 = w24 + w19;
  w19 = arg2[75];
  w19 = w19 * w22;
  w24 = w24 + w19;
  w19 = w30 * w24;
  w20 = w20 + w19;
  w19 = arg2[124];
  w22 = w13 * w19;
  w21 = arg2[125];
  w35 = w12 * w21;
  w22 = w22 + w35;
  w35 = arg2[126];
  w36 = w5 * w35;
  w22 = w22 + w36;
  w36 = arg0[1];
  w37 = w22 + w36;
  w38 = w20 + w37;
  w38 = w38 - w36;
  w39 = w11 * w38;
  w40 = w17 * w11;
  w41 = w3 * w2;
  w40 = w40 + w41;
  w41 = w6 * w1;
  w40 = w40 + w41;
  w41 = w40 * w7;
  w42 = w23 * w11;
  w43 = w25 * w2;
  w42 = w42 + w43;
  w43 = w26 * w1;
  w42 = w42 + w43;
  w43 = w42 * w27;
  w44 = w29 * w11;
  w45 = w31 * w2;
  w44 = w44 + w45;
  w45 = w32 * w1;
  w44 = w44 + w45;
  w45 = w44 * w33;
  w43 = w43 + w45;
  w45 = w43 * w34;
  w41 = w41 + w45;
  w44 = w44 * w27;
  w42 = w42 * w33;
  w44 = w44 - w42;
  w42 = w44 * w24;
  w41 = w41 + w42;
  w42 = w11 * w19;
  w45 = w2 * w21;
  w42 = w42 + w45;
  w45 = w1 * w35;
  w42 = w42 + w45;
  w45 = arg0[0];
  w46 = w42 + w45;
  w47 = w41 + w46;
  w47 = w47 - w45;
  w48 = w13 * w47;
  w39 = w39 - w48;
  res0[13] = w39;
  w39 = arg2[114];
  w48 = w8 * w39;
  w49 = arg2[112];
  w50 = w49 * w28;
  w48 = w48 + w50;
  w50 = arg2[113];
  w51 = w50 * w30;
  w48 = w48 + w51;
  w51 = arg2[85];
  w52 = arg3[6];
  w51 = w51 * w52;
  w53 = arg2[86];
  w54 = arg3[7];
  w53 = w53 * w54;
  w51 = w51 + w53;
  w53 = arg2[87];
  w55 = arg3[8];
  w53 = w53 * w55;
  w51 = w51 + w53;
  w53 = w48 * w51;
  w56 = arg2[108];
  w57 = w8 * w56;
  w58 = arg2[106];
  w59 = w58 * w28;
  w57 = w57 + w59;
  w59 = arg2[107];
  w60 = w59 * w30;
  w57 = w57 + w60;
  w60 = arg4[1];
  w61 = w57 * w60;
  w62 = arg2[111];
  w63 = w8 * w62;
  w64 = arg2[109];
  w65 = w64 * w28;
  w63 = w63 + w65;
  w65 = arg2[110];
  w66 = w65 * w30;
  w63 = w63 + w66;
  w66 = arg5[1];
  w67 = w63 * w66;
  w61 = w61 + w67;
  w67 = arg2[79];
  w67 = w67 * w52;
  w68 = arg2[80];
  w68 = w68 * w54;
  w67 = w67 + w68;
  w68 = arg2[81];
  w68 = w68 * w55;
  w67 = w67 + w68;
  w68 = w61 * w67;
  w53 = w53 + w68;
  w63 = w63 * w60;
  w57 = w57 * w66;
  w63 = w63 - w57;
  w57 = arg2[82];
  w57 = w57 * w52;
  w52 = arg2[83];
  w52 = w52 * w54;
  w57 = w57 + w52;
  w52 = arg2[84];
  w52 = w52 * w55;
  w57 = w57 + w52;
  w52 = w63 * w57;
  w53 = w53 + w52;
  w52 = arg2[129];
  w55 = w8 * w52;
  w54 = arg2[127];
  w28 = w28 * w54;
  w55 = w55 + w28;
  w28 = arg2[128];
  w30 = w30 * w28;
  w55 = w55 + w30;
  w30 = w55 + w37;
  w68 = w53 + w30;
  w69 = w68 - w36;
  w70 = w11 * w69;
  w71 = w40 * w39;
  w72 = w49 * w43;
  w71 = w71 + w72;
  w72 = w50 * w44;
  w71 = w71 + w72;
  w72 = w71 * w51;
  w73 = w40 * w56;
  w74 = w58 * w43;
  w73 = w73 + w74;
  w74 = w59 * w44;
  w73 = w73 + w74;
  w74 = w73 * w60;
  w75 = w40 * w62;
  w76 = w64 * w43;
  w75 = w75 + w76;
  w76 = w65 * w44;
  w75 = w75 + w76;
  w76 = w75 * w66;
  w74 = w74 + w76;
  w76 = w74 * w67;
  w72 = w72 + w76;
  w75 = w75 * w60;
  w73 = w73 * w66;
  w75 = w75 - w73;
  w73 = w75 * w57;
  w72 = w72 + w73;
  w73 = w40 * w52;
  w43 = w43 * w54;
  w73 = w73 + w43;
  w44 = w44 * w28;
  w73 = w73 + w44;
  w44 = w73 + w46;
  w43 = w72 + w44;
  w76 = w43 - w45;
  w77 = w13 * w76;
  w70 = w70 - w77;
  res0[14] = w70;
  w70 = arg2[123];
  w77 = w48 * w70;
  w78 = arg2[121];
  w79 = w78 * w61;
  w77 = w77 + w79;
  w79 = arg2[122];
  w80 = w79 * w63;
  w77 = w77 + w80;
  w80 = arg2[94];
  w81 = arg3[9];
  w80 = w80 * w81;
  w82 = arg2[95];
  w83 = arg3[10];
  w82 = w82 * w83;
  w80 = w80 + w82;
  w82 = arg2[96];
  w84 = arg3[11];
  w82 = w82 * w84;
  w80 = w80 + w82;
  w82 = w77 * w80;
  w85 = arg2[117];
  w86 = w48 * w85;
  w87 = arg2[115];
  w88 = w87 * w61;
  w86 = w86 + w88;
  w88 = arg2[116];
  w89 = w88 * w63;
  w86 = w86 + w89;
  w89 = arg4[2];
  w90 = w86 * w89;
  w91 = arg2[120];
  w92 = w48 * w91;
  w93 = arg2[118];
  w94 = w93 * w61;
  w92 = w92 + w94;
  w94 = arg2[119];
  w95 = w94 * w63;
  w92 = w92 + w95;
  w95 = arg5[2];
  w96 = w92 * w95;
  w90 = w90 + w96;
  w96 = arg2[88];
  w96 = w96 * w81;
  w97 = arg2[89];
  w97 = w97 * w83;
  w96 = w96 + w97;
  w97 = arg2[90];
  w97 = w97 * w84;
  w96 = w96 + w97;
  w90 = w90 * w96;
  w82 = w82 + w90;
  w92 = w92 * w89;
  w86 = w86 * w95;
  w92 = w92 - w86;
  w86 = arg2[91];
  w86 = w86 * w81;
  w81 = arg2[92];
  w81 = w81 * w83;
  w86 = w86 + w81;
  w81 = arg2[93];
  w81 = w81 * w84;
  w86 = w86 + w81;
  w92 = w92 * w86;
  w82 = w82 + w92;
  w92 = arg2[132];
  w81 = w48 * w92;
  w84 = arg2[130];
  w61 = w61 * w84;
  w81 = w81 + w61;
  w61 = arg2[131];
  w63 = w63 * w61;
  w81 = w81 + w63;
  w63 = w81 + w30;
  w63 = w82 + w63;
  w36 = w63 - w36;
  w83 = w11 * w36;
  w90 = w71 * w70;
  w97 = w78 * w74;
  w90 = w90 + w97;
  w97 = w79 * w75;
  w90 = w90 + w97;
  w97 = w90 * w80;
  w98 = w71 * w85;
  w99 = w87 * w74;
  w98 = w98 + w99;
  w99 = w88 * w75;
  w98 = w98 + w99;
  w99 = w98 * w89;
  w100 = w71 * w91;
  w101 = w93 * w74;
  w100 = w100 + w101;
  w101 = w94 * w75;
  w100 = w100 + w101;
  w101 = w100 * w95;
  w99 = w99 + w101;
  w99 = w99 * w96;
  w97 = w97 + w99;
  w100 = w100 * w89;
  w98 = w98 * w95;
  w100 = w100 - w98;
  w100 = w100 * w86;
  w97 = w97 + w100;
  w100 = w71 * w92;
  w74 = w74 * w84;
  w100 = w100 + w74;
  w75 = w75 * w61;
  w100 = w100 + w75;
  w75 = w100 + w44;
  w75 = w97 + w75;
  w45 = w75 - w45;
  w74 = w13 * w45;
  w83 = w83 - w74;
  res0[15] = w83;
  w83 = w2 * w16;
  w74 = w12 * w18;
  w83 = w83 - w74;
  res0[16] = w83;
  w83 = w2 * w38;
  w74 = w12 * w47;
  w83 = w83 - w74;
  res0[17] = w83;
  w83 = w2 * w69;
  w74 = w12 * w76;
  w83 = w83 - w74;
  res0[18] = w83;
  w83 = w2 * w36;
  w74 = w12 * w45;
  w83 = w83 - w74;
  res0[19] = w83;
  w83 = w1 * w16;
  w74 = w5 * w18;
  w83 = w83 - w74;
  res0[20] = w83;
  w38 = w1 * w38;
  w47 = w5 * w47;
  w38 = w38 - w47;
  res0[21] = w38;
  w69 = w1 * w69;
  w76 = w5 * w76;
  w69 = w69 - w76;
  res0[22] = w69;
  w36 = w1 * w36;
  w45 = w5 * w45;
  w36 = w36 - w45;
  res0[23] = w36;
  w36 = 0.0;
  res0[24] = w36;
  w45 = w40 * w20;
  w69 = w8 * w41;
  w45 = w45 - w69;
  res0[25] = w45;
  w68 = w68 - w37;
  w68 = w40 * w68;
  w43 = w43 - w46;
  w43 = w8 * w43;
  w68 = w68 - w43;
  res0[26] = w68;
  w37 = w63 - w37;
  w37 = w40 * w37;
  w46 = w75 - w46;
  w46 = w8 * w46;
  w37 = w37 - w46;
  res0[27] = w37;
  res0[28] = w36;
  res0[29] = w36;
  w37 = w71 * w53;
  w46 = w48 * w72;
  w37 = w37 - w46;
  res0[30] = w37;
  w63 = w63 - w30;
  w63 = w71 * w63;
  w75 = w75 - w44;
  w75 = w48 * w75;
  w63 = w63 - w75;
  res0[31] = w63;
  res0[32] = w36;
  res0[33] = w36;
  res0[34] = w36;
  w36 = w90 * w82;
  w63 = w77 * w97;
  w36 = w36 - w63;
  res0[35] = w36;
  w36 = arg1[3];
  w63 = w11 * w36;
  w75 = arg1[4];
  w44 = w2 * w75;
  w63 = w63 + w44;
  w44 = arg1[5];
  w30 = w1 * w44;
  w63 = w63 + w30;
  w30 = arg1[0];
  w37 = w13 * w30;
  w46 = arg1[1];
  w68 = w12 * w46;
  w37 = w37 + w68;
  w68 = arg1[2];
  w43 = w5 * w68;
  w37 = w37 + w43;
  w37 = w63 * w37;
  w13 = w13 * w36;
  w12 = w12 * w75;
  w13 = w13 + w12;
  w5 = w5 * w44;
  w13 = w13 + w5;
  w11 = w11 * w30;
  w2 = w2 * w46;
  w11 = w11 + w2;
  w1 = w1 * w68;
  w11 = w11 + w1;
  w11 = w13 * w11;
  w37 = w37 - w11;
  w36 = w4 * w36;
  w75 = w9 * w75;
  w36 = w36 + w75;
  w44 = w14 * w44;
  w36 = w36 + w44;
  w18 = w18 * w36;
  w15 = w4 * w15;
  w0 = w9 * w0;
  w15 = w15 + w0;
  w10 = w14 * w10;
  w15 = w15 + w10;
  w10 = w15 * w63;
  w18 = w18 - w10;
  w18 = w18 * w63;
  w18 = w37 + w18;
  w10 = w15 * w13;
  w16 = w16 * w36;
  w10 = w10 - w16;
  w10 = w10 * w13;
  w18 = w18 - w10;
  res1[0] = w18;
  w42 = w42 * w36;
  w19 = w4 * w19;
  w21 = w9 * w21;
  w19 = w19 + w21;
  w35 = w14 * w35;
  w19 = w19 + w35;
  w35 = w19 * w63;
  w42 = w42 - w35;
  w42 = w63 * w42;
  w37 = w37 + w42;
  w42 = w19 * w13;
  w22 = w22 * w36;
  w42 = w42 - w22;
  w42 = w13 * w42;
  w37 = w37 - w42;
  w42 = arg1[6];
  w17 = w17 * w4;
  w3 = w3 * w9;
  w17 = w17 + w3;
  w6 = w6 * w14;
  w17 = w17 + w6;
  w6 = w17 * w13;
  w3 = w8 * w36;
  w6 = w6 - w3;
  w6 = w42 * w6;
  w3 = w6 * w20;
  w3 = w37 + w3;
  w22 = w17 * w42;
  w22 = w36 + w22;
  w35 = w41 * w22;
  w7 = w17 * w7;
  w23 = w23 * w4;
  w25 = w25 * w9;
  w23 = w23 + w25;
  w26 = w26 * w14;
  w23 = w23 + w26;
  w26 = w23 * w27;
  w29 = w29 * w4;
  w31 = w31 * w9;
  w29 = w29 + w31;
  w32 = w32 * w14;
  w29 = w29 + w32;
  w32 = w29 * w33;
  w26 = w26 + w32;
  w34 = w26 * w34;
  w7 = w7 + w34;
  w29 = w29 * w27;
  w23 = w23 * w33;
  w29 = w29 - w23;
  w24 = w29 * w24;
  w7 = w7 + w24;
  w24 = w40 * w42;
  w24 = w63 + w24;
  w23 = w7 * w24;
  w35 = w35 - w23;
  w35 = w35 * w24;
  w3 = w3 + w35;
  w40 = w40 * w36;
  w63 = w17 * w63;
  w40 = w40 - w63;
  w40 = w42 * w40;
  w41 = w40 * w41;
  w3 = w3 - w41;
  w8 = w8 * w42;
  w13 = w13 + w8;
  w8 = w7 * w13;
  w20 = w20 * w22;
  w8 = w8 - w20;
  w8 = w8 * w13;
  w3 = w3 - w8;
  res1[1] = w3;
  w3 = w6 * w55;
  w37 = w37 + w3;
  w3 = w73 * w22;
  w52 = w17 * w52;
  w54 = w26 * w54;
  w52 = w52 + w54;
  w28 = w29 * w28;
  w52 = w52 + w28;
  w28 = w52 * w24;
  w3 = w3 - w28;
  w3 = w24 * w3;
  w37 = w37 + w3;
  w73 = w40 * w73;
  w37 = w37 - w73;
  w73 = w52 * w13;
  w55 = w55 * w22;
  w73 = w73 - w55;
  w73 = w13 * w73;
  w37 = w37 - w73;
  w73 = arg1[7];
  w39 = w17 * w39;
  w49 = w49 * w26;
  w39 = w39 + w49;
  w50 = w50 * w29;
  w39 = w39 + w50;
  w50 = w39 * w13;
  w49 = w48 * w22;
  w50 = w50 - w49;
  w50 = w73 * w50;
  w6 = w6 + w50;
  w50 = w6 * w53;
  w50 = w37 + w50;
  w49 = w39 * w73;
  w49 = w22 + w49;
  w55 = w72 * w49;
  w51 = w39 * w51;
  w56 = w17 * w56;
  w58 = w58 * w26;
  w56 = w56 + w58;
  w59 = w59 * w29;
  w56 = w56 + w59;
  w59 = w56 * w60;
  w17 = w17 * w62;
  w64 = w64 * w26;
  w17 = w17 + w64;
  w65 = w65 * w29;
  w17 = w17 + w65;
  w65 = w17 * w66;
  w59 = w59 + w65;
  w67 = w59 * w67;
  w51 = w51 + w67;
  w17 = w17 * w60;
  w56 = w56 * w66;
  w17 = w17 - w56;
  w57 = w17 * w57;
  w51 = w51 + w57;
  w57 = w71 * w73;
  w57 = w24 + w57;
  w56 = w51 * w57;
  w55 = w55 - w56;
  w55 = w55 * w57;
  w50 = w50 + w55;
  w71 = w71 * w22;
  w24 = w39 * w24;
  w71 = w71 - w24;
  w71 = w73 * w71;
  w40 = w40 + w71;
  w72 = w40 * w72;
  w50 = w50 - w72;
  w48 = w48 * w73;
  w13 = w13 + w48;
  w48 = w51 * w13;
  w53 = w53 * w49;
  w48 = w48 - w53;
  w48 = w48 * w13;
  w50 = w50 - w48;
  res1[2] = w50;
  w50 = w6 * w81;
  w37 = w37 + w50;
  w50 = w100 * w49;
  w92 = w39 * w92;
  w84 = w59 * w84;
  w92 = w92 + w84;
  w61 = w17 * w61;
  w92 = w92 + w61;
  w61 = w92 * w57;
  w50 = w50 - w61;
  w50 = w57 * w50;
  w37 = w37 + w50;
  w100 = w40 * w100;
  w37 = w37 - w100;
  w100 = w92 * w13;
  w81 = w81 * w49;
  w100 = w100 - w81;
  w100 = w13 * w100;
  w37 = w37 - w100;
  w100 = arg1[8];
  w70 = w39 * w70;
  w78 = w78 * w59;
  w70 = w70 + w78;
  w79 = w79 * w17;
  w70 = w70 + w79;
  w79 = w70 * w13;
  w78 = w77 * w49;
  w79 = w79 - w78;
  w79 = w100 * w79;
  w6 = w6 + w79;
  w6 = w6 * w82;
  w37 = w37 + w6;
  w6 = w70 * w100;
  w6 = w49 + w6;
  w79 = w97 * w6;
  w80 = w70 * w80;
  w85 = w39 * w85;
  w87 = w87 * w59;
  w85 = w85 + w87;
  w88 = w88 * w17;
  w85 = w85 + w88;
  w88 = w85 * w89;
  w39 = w39 * w91;
  w93 = w93 * w59;
  w39 = w39 + w93;
  w94 = w94 * w17;
  w39 = w39 + w94;
  w94 = w39 * w95;
  w88 = w88 + w94;
  w88 = w88 * w96;
  w80 = w80 + w88;
  w39 = w39 * w89;
  w85 = w85 * w95;
  w39 = w39 - w85;
  w39 = w39 * w86;
  w80 = w80 + w39;
  w39 = w90 * w100;
  w39 = w57 + w39;
  w86 = w80 * w39;
  w79 = w79 - w86;
  w79 = w79 * w39;
  w37 = w37 + w79;
  w90 = w90 * w49;
  w70 = w70 * w57;
  w90 = w90 - w70;
  w90 = w100 * w90;
  w40 = w40 + w90;
  w40 = w40 * w97;
  w37 = w37 - w40;
  w77 = w77 * w100;
  w13 = w13 + w77;
  w77 = w80 * w13;
  w82 = w82 * w6;
  w77 = w77 - w82;
  w77 = w77 * w13;
  w37 = w37 - w77;
  res1[3] = w37;
  w37 = arg0[2];
  w15 = w15 + w37;
  res2[0] = w15;
  w19 = w19 + w37;
  w7 = w7 + w19;
  res2[1] = w7;
  w52 = w52 + w19;
  w51 = w51 + w52;
  res2[2] = w51;
  w92 = w92 + w52;
  w80 = w80 + w92;
  res2[3] = w80;
}


CASADI_SYMBOL_EXPORT int snakecg_sp3_batch_ground_rows(casadi_int n, const casadi_real** arg,
    const casadi_int* stride, casadi_real** res) {
  const casadi_real* a[4];
  casadi_real* r[3];
  casadi_int* iw = (casadi_int*) malloc(sizeof(casadi_int) * 1);
  casadi_real* w = (casadi_real*) malloc(sizeof(casadi_real) * 103);
  casadi_int i, k;
  int status = 0;
  if (!iw || !w) { free(iw); free(w); return -1; }
  for (k = 0; k < 4; ++k) a[k] = 0;
  for (k = 0; k < 3; ++k) r[k] = 0;
  if (arg[0] && arg[1] && arg[2] && arg[3] && res[0] && res[1] && res[2]) {
    /* cos and sin of q[7..9] of 16 samples at a time, then snakecg_sp3_ground_rows_sincos
     * per sample (a batch of one too, so that a batch equals its samples one by one) */
    const casadi_int na = 3, per = 16;
    casadi_real ang[48], ca[48], sa[48];
    casadi_int i0, m;
    int large;
    for (k = 0; k < 48; ++k) ang[k] = 0;
    for (i0 = 0; i0 < n; i0 += per) {
      m = n - i0 < per ? n - i0 : per;
      large = 0;
      for (i = 0; i < m; ++i) {
        const casadi_real* q = arg[0] + (i0 + i) * stride[0] + 7;
        for (k = 0; k < na; ++k) {
          ang[i * na + k] = q[k];
          large |= !(fabs(q[k]) <= SNAKECG_SINCOS_MAX);
        }
      }
      for (k = 0; k < m * na; k += SNAKECG_SINCOS_BLOCK) {
        snakecg_sincos_block(ang + k, ca + k, sa + k);
      }
      if (large) snakecg_sincos_large(ang, ca, sa, m * na);
      for (i = 0; i < m; ++i) {
        snakecg_sp3_ground_rows_sincos(arg[0] + (i0 + i) * stride[0], arg[1] + (i0 + i) * stride[1], arg[2] + (i0 + i) * stride[2], arg[3] + (i0 + i) * stride[3], ca + i * na, sa + i * na, res[0] + (i0 + i) * 36, res[1] + (i0 + i) * 4, res[2] + (i0 + i) * 4);
      }
    }
  } else {
    /* a null input or output (CasADi's convention: zeros in, nothing out): per sample */
    for (i = 0; i < n; ++i) {
      a[0] = arg[0] + i * stride[0];
      a[1] = arg[1] + i * stride[1];
      a[2] = arg[2] + i * stride[2];
      a[3] = arg[3] + i * stride[3];
      r[0] = res[0] + i * 36;
      r[1] = res[1] + i * 4;
      r[2] = res[2] + i * 4;
      if (snakecg_sp3_ground_rows(a, r, iw, w, 0)) { status = (int) (i + 1); break; }
    }
  }
  free(iw);
  free(w);
  return status;
}
