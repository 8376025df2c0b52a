MODULE MainModule
  ! Tests: SetSysData makes a tool the current one (CTool reads it back) and GetSysData copies
  ! the current work object; ModExist knows the loaded modules.
  PERS tooldata tGripper := [TRUE,[[0,0,150],[1,0,0,0]],[1.5,[0,0,60],[1,0,0,0],0,0,0]];
  PERS wobjdata wCurrent := [FALSE,TRUE,"",[[1,2,3],[1,0,0,0]],[[0,0,0],[1,0,0,0]]];
  PROC main()
    SetSysData tGripper;
    TPWrite "tool z " \Num:=CTool().tframe.trans.z;
    GetSysData wCurrent;
    TPWrite "wobj x " \Num:=wCurrent.uframe.trans.x;
    IF ModExist("MainModule") TPWrite "MainModule loaded";
    IF NOT ModExist("CalibData") TPWrite "no CalibData";
  ENDPROC
ENDMODULE
