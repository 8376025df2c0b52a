MODULE record_nested
  ! Tests: records nest: a component of a record component is assigned and
  ! read through a chain of dots; nested aggregates initialise them.
  RECORD segment
    pos start;
    pos stop;
  ENDRECORD
  PROC main()
    VAR segment s := [[1, 2, 3], [4, 5, 6]];
    s.stop.y := 50;
    TPWrite "start=" \Pos:=s.start;
    TPWrite "stop=" \Pos:=s.stop;
    TPWrite "z=" \Num:=s.start.z + s.stop.z;
  ENDPROC
ENDMODULE
