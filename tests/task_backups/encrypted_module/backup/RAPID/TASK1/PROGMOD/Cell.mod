MODULE Cell
    ! Written for the test (issue 28): the robot task uses a licensed add-in whose modules
    ! are encrypted. LicReceiver.sys (encrypted) declares LicInit and the PERS bLicenseOk;
    ! the task T_LICENSE, encrypted throughout, sets it. Checked without the encrypted code,
    ! the wait on bLicenseOk is no deadlock (written from outside), and the index the
    ! operator's branch leaves 0 stays found.
    VAR num slots{3} := [10, 20, 30];
    VAR num slot := 0;
    VAR num key := 0;

    PROC main()
        LicInit;
        WaitUntil bLicenseOk;
        TPReadFK key, "Slot?", "Left", "Right", "Skip", stEmpty, stEmpty;
        IF key = 1 THEN
            slot := 1;
        ELSEIF key = 2 THEN
            slot := 3;
        ENDIF
        TPWrite "slot value" \Num:=slots{slot};
    ENDPROC
ENDMODULE
