MODULE PredefinedData
    ! reg1 is the controller's own PERS num, declared in no module: it is no assumption
    ! of the program's (it used to stop the check with an internal error, issue 19).
    PERS num nSpeed := 100;

    PROC main()
        TPWrite "reg1 " \Num:=reg1;
        TPWrite "speed " \Num:=nSpeed;
    ENDPROC
ENDMODULE
