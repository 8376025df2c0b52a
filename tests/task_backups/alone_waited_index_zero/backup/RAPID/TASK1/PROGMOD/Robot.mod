MODULE Robot
    ! Written for the test (issue 28): robot 1 waits until the PLC names a station, then
    ! takes its offset. A station code other than 1 or 2 leaves the index 0: a true defect,
    ! which the value the wait took (kept for the reads after it) still shows.
    PERS num nStation := 0;
    VAR num offsets{2} := [100, 200];
    VAR num slot := 0;

    PROC main()
        WaitUntil nStation <> 0;
        slot := 0;
        TEST nStation
        CASE 1:
            slot := 1;
        CASE 2:
            slot := 2;
        ENDTEST
        TPWrite "offset" \Num:=offsets{slot};
    ENDPROC
ENDMODULE
