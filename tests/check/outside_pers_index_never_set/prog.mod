MODULE OutsideIndexNeverSet
    ! Issue 28, a true defect that must stay found with data written from outside: the
    ! PLC's part code sets the slot in two branches, any other code leaves it 0, and
    ! slots{0} is out of bounds.
    PERS num nPartCode := 0;
    PERS bool bPartReady := FALSE;
    VAR num slots{3} := [10, 20, 30];
    VAR num slot := 0;
    VAR num target := 0;

    PROC main()
        WaitUntil bPartReady;
        IF nPartCode = 1 THEN
            slot := 1;
        ELSEIF nPartCode = 2 THEN
            slot := 3;
        ENDIF
        target := slots{slot};
    ENDPROC
ENDMODULE
