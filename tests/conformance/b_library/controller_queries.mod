MODULE MainModule
  ! Tests: IsSysId compares with the controller's serial number (GetSysInfo \SerialNo);
  ! GetNextMechUnit lists ROB_1 at entry 0 and nothing after, incrementing ListNumber each
  ! call; GetModalPayLoadMode reads 1; CheckProgRef, DitherAct and DitherDeact change nothing.
  PROC main()
    VAR num listno := 0;
    VAR string unit := "";
    VAR num axes := 0;
    VAR bool tcprob := FALSE;
    VAR bool found;
    IF IsSysId(GetSysInfo(\SerialNo)) TPWrite "own system id";
    IF NOT IsSysId("6400-123456") TPWrite "other system id";
    found := GetNextMechUnit(listno, unit \TCPRob:=tcprob \NoOfAxes:=axes);
    TPWrite unit + " " + ValToStr(found) + " " + ValToStr(tcprob) + " " + NumToStr(axes, 0);
    TPWrite "next " \Num:=listno;
    unit := "none";
    found := GetNextMechUnit(listno, unit);
    TPWrite unit + " " + ValToStr(found) + " " + NumToStr(listno, 0);
    TPWrite "payload mode " \Num:=GetModalPayLoadMode();
    CheckProgRef;
    DitherAct \MechUnit:=ROB_1, 2 \Level:=50;
    DitherDeact;
    TPWrite "done";
  ENDPROC
ENDMODULE
