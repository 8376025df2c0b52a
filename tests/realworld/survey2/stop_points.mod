MODULE Palletizer
  ! stoppoint values (inpos, stoptime, fllwtime) in stoppointdata
  CONST stoppointdata my_inpos := [inpos, TRUE, [0, 0, 0.1, 5], 0, 0, "", 0, 0];
  VAR stoppointdata my_stop := [stoptime, FALSE, [0, 0, 0, 0], 0.5, 0, "", 0, 0];
  CONST robtarget pPlace := [[400,0,300],[1,0,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PROC main()
    MoveL pPlace, v100, fine \Inpos:=my_inpos, tool0;
    my_stop.type := fllwtime;
    TEST my_stop.type
    CASE inpos:
      TPWrite "in position";
    CASE stoptime:
      TPWrite "stop time";
    CASE fllwtime:
      TPWrite "follow time";
    ENDTEST
  ENDPROC
ENDMODULE
