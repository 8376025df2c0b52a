MODULE MainModule
  ! Tests: ValToStr of nested records (orient, pose) uses nested aggregates without spaces.
  PROC main()
    VAR orient o := [1, 0, 0, 0];
    VAR pose frame := [[10, 20, 30], [0, 0, 0, 1]];
    VAR confdata cf := [1, -1, 0, 1];
    TPWrite ValToStr(o);
    TPWrite ValToStr(frame);
    TPWrite ValToStr(cf);
  ENDPROC
ENDMODULE
