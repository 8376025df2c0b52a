MODULE Reader
  PERS tooldata tGun;
  PERS tooldata tGrip;
  PERS wobjdata wTable;
  VAR robtarget here;
  PROC main()
    here := CRobT(\Tool:=tGun \WObj:=wTable); ! LOCAL
    MoveJ here, v100, fine, tGun;        ! LOCAL
    tGrip.tframe.trans.z := 60;          ! SHARED
  ENDPROC
ENDMODULE
