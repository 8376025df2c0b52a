MODULE MainModule
  ! Tests: names of the reference added for issue 8, item 1. GetSignalOrigin tells a
  ! configured signal (SIGORIG_CFG, its name), signal data bound by AliasIO (SIGORIG_ALIAS,
  ! the configured signal's name) and signal data bound to nothing (SIGORIG_NONE, "");
  ! IOBusState reads a running bus; Type names the data type of its argument (of an array:
  ! the element type); TriggLIOs and ArcL1 move the robot to their target; SearchExtJ
  ! without a hit (the signal is 0 in run) raises ERR_WHLSEARCH after moving the external
  ! axes; a trigger is always valid; no cyclic bool exists; usbdisk1 is a file-system prefix;
  ! MirPos mirrors a point in the xy-plane of a frame (the tool's x- and z-axes mirrored, its
  ! y-axis turned) and EGMMoveL moves to its target.
  PERS robtarget pA := [[500,0,400],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PERS robtarget pB := [[600,0,300],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST jointtarget jExt := [[0,0,0,0,0,0],[250,9E9,9E9,9E9,9E9,9E9]];
  VAR jointtarget jFound;
  VAR signaldo doGripper;
  VAR signaldo doUnbound;
  VAR triggdata trigg;
  VAR triggios ios{1} := [[TRUE,10,TRUE,0,"doOut",1,0]];
  VAR busstate state;
  VAR string name;
  VAR num counts{3};
  VAR egmident egm;
  VAR robtarget pM;
  PERS wobjdata wMirror := [FALSE,TRUE,"",[[10,0,0],[0.707107,0,0.707107,0]],[[0,0,0],[1,0,0,0]]];
  PERS bool flag := FALSE;
  PROC main()
    Reset doOut;
    TPWrite "cfg " \Num:=GetSignalOrigin(doOut, name);
    TPWrite "cfg name " + name;
    AliasIO "doOut", doGripper;
    TPWrite "alias " + ValToStr(GetSignalOrigin(doGripper, name) = SIGORIG_ALIAS) + " " + name;
    TPWrite "none " + ValToStr(GetSignalOrigin(doUnbound, name) = SIGORIG_NONE) + " '" + name + "'";
    IOBusState "Local", state \Phys;
    TPWrite "bus " + ValToStr(state = IOBUS_PHYS_STATE_RUNNING);
    IOBusState "Local", state;
    TPWrite "bus " + ValToStr(state = BUSSTATE_RUN);
    TPWrite Type(pA) + " " + Type(state) + " " + Type(counts) + " " + Type(flag) + " " + Type(doGripper);
    TriggLIOs pB, v500 \TriggData1:=ios, fine, tool0;
    TPWrite "at x=" \Num:=CPos(\Tool:=tool0).x;
    TPWrite "trigger valid " + ValToStr(TriggDataValid(trigg));
    TPWrite "cyclic " + ValToStr(IsCyclicBool(flag)) + " " + NumToStr(GetNumberOfCyclicBool(), 0);
    TPWrite "usb " + usbdisk1;
    pM := MirPos(pA, wobj0);
    TPWrite "mirrored in xy " + ValToStr(pM.trans) + " " + ValToStr(pM.rot);
    pM := MirPos(pA, wMirror \MirY);
    TPWrite "mirrored at x=10 " + ValToStr(pM.trans) + " " + ValToStr(pM.rot);
    EGMMoveL egm, pA, v100, fine, tool0;
    TPWrite "at z=" \Num:=CPos(\Tool:=tool0).z;
    SearchExtJ \Stop, diProbe, jFound, jExt, v100;
    TPWrite "not reached";
  ERROR
    IF ERRNO = ERR_WHLSEARCH THEN
      TPWrite "no hit, ext axis a=" \Num:=CJointT().extax.eax_a;
      RETURN;
    ENDIF
  ENDPROC
ENDMODULE
