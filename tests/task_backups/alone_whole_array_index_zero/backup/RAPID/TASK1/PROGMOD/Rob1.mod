MODULE Rob1
    ! Written for the test (issue 28): each task sets its element of stReact; once all three
    ! are ready, robot 1 takes the station the PLC names in nStation (written outside).
    ! A station code other than 1 or 2 leaves the index 0: a true defect.
    PERS string stReact{3} := ["", "", ""];
    PERS num nStation := 0;
    VAR num offsets{2} := [100, 200];
    VAR num slot := 0;

    PROC main()
        stReact{1} := "Ready";
        WaitUntil stReact = ["Ready", "Ready", "Ready"];
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
