MODULE Robot
    ! Written for the test (issue 28): the job buffer is filled by the receiver task T_RX
    ! and cleared here; after its wait the robot reads the flag again, which only it clears.
    RECORD job
        bool ready;
        num code;
    ENDRECORD
    PERS job jobs{2} := [[FALSE, 0], [FALSE, 0]];
    VAR num slots{3} := [10, 20, 30];
    VAR num slot := 0;

    PROC main()
        WHILE TRUE DO
            WaitUntil jobs{1}.ready = TRUE;
            slot := 0;
            IF jobs{1}.ready slot := 2;
            TPWrite "slot value" \Num:=slots{slot};
            jobs{1}.ready := FALSE;
        ENDWHILE
    ENDPROC
ENDMODULE
