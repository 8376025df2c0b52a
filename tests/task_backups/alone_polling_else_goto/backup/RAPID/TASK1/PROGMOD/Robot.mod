MODULE Robot
    ! Written for the test (issue 28): the job buffer is filled by the receiver task T_RX
    ! and cleared here, so both tasks write it; the robot polls it with IF ... ELSE GOTO.
    RECORD job
        bool ready;
        num code;
    ENDRECORD
    PERS job jobs{2} := [[FALSE, 0], [FALSE, 0]];
    VAR num slots{3} := [10, 20, 30];
    VAR num slot := 0;

    PROC main()
        WHILE TRUE DO
        again:
            IF jobs{1}.ready THEN
                TEST jobs{1}.code
                CASE 1:
                    slot := 1;
                CASE 2:
                    slot := 3;
                ENDTEST
                TPWrite "slot value" \Num:=slots{slot};
                jobs{1}.ready := FALSE;
            ELSE
                WaitTime 0.1;
                GOTO again;
            ENDIF
        ENDWHILE
    ENDPROC
ENDMODULE
