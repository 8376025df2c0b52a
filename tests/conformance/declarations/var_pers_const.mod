MODULE var_pers_const
  ! Tests: the three storage classes: a CONST is read, a VAR and a PERS are
  ! read and written; initialisers may use CONSTs.
  CONST num K := 5;
  VAR num v := K * 2;
  PERS num p := 3;
  PROC main()
    p := p + v;
    v := v - K;
    TPWrite "p=" \Num:=p;
    TPWrite "v=" \Num:=v;
    TPWrite "K=" \Num:=K;
  ENDPROC
ENDMODULE
