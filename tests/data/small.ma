//Maya ASCII 2020 scene
requires maya "2020";
currentUnit -l centimeter -a degree -t film;
createNode transform -n "plane1";
	setAttr ".t" -type "double3" 0 1 0 ;
createNode mesh -n "planeShape1" -p "plane1";
	setAttr -k off ".v";
	setAttr ".uvst[0].uvsn" -type "string" "map1";
	setAttr -s 6 ".uvst[0].uvsp[0:5]" -type "float2" 0 0 0.5 0 1 0 0 1 0.5 1 1 1;
	setAttr -s 6 ".vt[0:5]"  -2 0 1 0 0 1 2 0 1 -2 0 -1 0 0 -1 2 0 -1;
	setAttr -s 7 ".ed[0:6]"  0 1 0 1 2 0 3 4 0 4 5 0 0 3 0 1 4 0 2 5 0;
	setAttr -s 2 -ch 8 ".fc[0:1]" -type "polyFaces"
		f 4 0 5 -3 -5
		mu 0 4 0 1 4 3
		f 4 1 6 -4 -6
		mu 0 4 1 2 5 4 ;
createNode transform -n "hairSystem1";
createNode hairSystem -n "hairSystemShape1" -p "hairSystem1";
	setAttr ".hpc" 16;
	setAttr ".cwd" 0.2;
	setAttr ".hwd" 0.03;
	setAttr ".ssg" 2;
	setAttr -s 2 ".cws[0:1]"  0 1 3 1 0.2 3;
	setAttr ".clc[0]"  0 0.6 1;
	setAttr ".hcl" -type "float3" 0.5 0.3 0.1 ;
	setAttr ".hcs[0].hcsp" 0;
	setAttr ".hcs[0].hcsc" -type "float3" 0.5 0.5 0.5 ;
	setAttr ".hcs[0].hcsi" 1;
	setAttr ".hcs[1].hcsp" 1;
	setAttr ".hcs[1].hcsc" -type "float3" 1 1 1 ;
	setAttr ".nmt" 1;
createNode transform -n "hairSystem1Follicles";
createNode transform -n "follicle1" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" -1 1 0 ;
createNode follicle -n "follicleShape1" -p "follicle1";
	setAttr ".pu" 0.25;
	setAttr ".pv" 0.5;
createNode transform -n "curve1" -p "follicle1";
createNode nurbsCurve -n "curveShape1" -p "curve1";
	setAttr ".cc" -type "nurbsCurve"
		3 2 0 no 3
		7 0 0 0 1 2 2 2
		5
		0 0 0
		0 0.5 0
		0 1 0.5
		0 1.5 0.5
		0 2 0
		;
createNode transform -n "follicle2" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" 1 1 0 ;
createNode follicle -n "follicleShape2" -p "follicle2";
	setAttr ".pu" 0.75;
	setAttr ".pv" 0.5;
createNode transform -n "curve2" -p "follicle2";
createNode nurbsCurve -n "curveShape2" -p "curve2";
	setAttr ".cc" -type "nurbsCurve"
		1 3 0 no 3
		4 0 1 2 3
		4
		0 0 0
		0 1 0
		0.5 1 0
		0.5 2 0
		;
createNode transform -n "follicle3" -p "hairSystem1Follicles";
createNode follicle -n "follicleShape3" -p "follicle3";
	setAttr ".pu" 0.75;
	setAttr ".pv" 0.25;
createNode transform -n "curve3" -p "follicle3";
createNode nurbsCurve -n "curveShape3" -p "curve3";
	setAttr ".cc" -type "nurbsCurve"
		1 1 0 no 3
		2 0 1
		2
		0 0 0
		1 0 0
		;
createNode FurDescription -n "FurDescription1";
	setAttr ".d" 5000;
	setAttr ".dl" 0.4;
	setAttr ".dbw" 0.02;
	setAttr ".dbc" -type "float3" 0.6 0.4 0.2 ;
createNode transform -n "FurFeedback1";
createNode FurFeedback -n "FurFeedbackShape1" -p "FurFeedback1";
createNode transform -n "camera1";
	setAttr ".t" -type "double3" 0 3 10 ;
createNode camera -n "cameraShape1" -p "camera1";
	setAttr ".fl" 50;
	setAttr ".coi" 10;
createNode transform -n "directionalLight1";
	setAttr ".r" -type "double3" -90 0 0 ;
createNode directionalLight -n "directionalLightShape1" -p "directionalLight1";
	setAttr ".in" 2;
createNode transform -n "ctrl";
createNode nurbsCurve -n "ctrlShape" -p "ctrl";
	setAttr ".cc" -type "nurbsCurve"
		1 4 2 no 3
		5 0 1 2 3 4
		5
		1 0 0 0 0 1 -1 0 0 0 0 -1 1 0 0
		;
createNode polyCube -n "polyCube1";
createNode polyCube -n "polyCube2";
select -ne :defaultResolution;
	setAttr ".w" 320;
	setAttr ".h" 240;
connectAttr "planeShape1.o" "follicleShape1.inm";
connectAttr "planeShape1.o" "follicleShape2.inm";
connectAttr "planeShape1.o" "follicleShape3.inm";
connectAttr "planeShape1.wm" "follicleShape3.iwm";
connectAttr "follicleShape3.ot" "follicle3.t";
connectAttr "follicleShape3.or" "follicle3.r";
connectAttr "curveShape1.ws" "follicleShape1.sp";
connectAttr "curveShape2.ws" "follicleShape2.sp";
connectAttr "curveShape3.ws" "follicleShape3.sp";
connectAttr "follicleShape1.oha" "hairSystemShape1.ih[0]";
connectAttr "follicleShape2.oha" "hairSystemShape1.ih[1]";
connectAttr "follicleShape3.oha" "hairSystemShape1.ih[2]";
connectAttr "planeShape1.w" "FurFeedbackShape1.imsh";
connectAttr "FurDescription1.dl" "FurFeedbackShape1.dl";
