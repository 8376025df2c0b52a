MODULE BrokenSyntax
  ! Tests: every statement with a syntax error is reported, not only the first.
  VAR num counter := ;
  PROC main()
    counter := counter +;
    IF counter > 1 THEN
      MoveL pHome, v100 fine, tool0;
    ENDIF
    counter := (counter + 2;
    TPWrite "done; really" \Num:=;
  ENDPROC
ENDMODULE
