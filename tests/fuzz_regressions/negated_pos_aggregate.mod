! expect: exit 0
! Unary minus on a pos aggregate, also in a CONST initialiser (once: TypeError on tuple).
MODULE NegatedPos
  CONST pos PLACE := -[300, 600, 150];
  PROC main()
    VAR pos p;
    p := -[1, 2, 3];
    TPWrite "p" \Pos:=p;
    TPWrite "PLACE" \Pos:=PLACE;
  ENDPROC
ENDMODULE
