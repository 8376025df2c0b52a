MODULE and_binds_tighter_than_or
  ! Tests: AND binds tighter than OR and XOR: TRUE OR FALSE AND FALSE is
  ! TRUE OR (FALSE AND FALSE) = TRUE (left-to-right would give FALSE).
  PROC main()
    VAR bool t := TRUE;
    VAR bool f := FALSE;
    TPWrite "t OR f AND f: " \Bool:=t OR f AND f;
    TPWrite "f XOR t AND t: " \Bool:=f XOR t AND t;
    TPWrite "t XOR t: " \Bool:=t XOR t;
    TPWrite "f AND t OR t AND t: " \Bool:=f AND t OR t AND t;
  ENDPROC
ENDMODULE
