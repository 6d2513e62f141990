// sim/ starts here
