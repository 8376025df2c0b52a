MODULE UnsetIndexOwnBranch
    ! Issue 28, a true defect that must stay found: the slot is declared without a value
    ! and only the program's own branch sets it. It is the program's data, not data
    ! written outside, so it starts at 0: a part code other than 1 leaves slots{0}.
    PERS num nSlot;
    PERS num nPartCode;
    VAR num slots{3} := [10, 20, 30];
    VAR num target := 0;

    PROC main()
        IF nPartCode = 1 THEN
            nSlot := 2;
        ENDIF
        target := slots{nSlot};
    ENDPROC
ENDMODULE
