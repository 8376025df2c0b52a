MODULE const_expression_chain
  ! Tests: a CONST initialiser is a constant expression that may use earlier
  ! CONSTs and operators (precedence applies).
  CONST num A := 2;
  CONST num B := A * 3 + 1;
  CONST string S := "v" + "1";
  CONST bool FLAG := B > A;
  PROC main()
    TPWrite S + "=" \Num:=B;
    TPWrite "flag " \Bool:=FLAG;
  ENDPROC
ENDMODULE
